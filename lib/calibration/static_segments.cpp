#include "lib/calibration/static_segments.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace insmc::calibration {
namespace {

/// Variance of one component over samples [b, e).
template <class Get>
double window_variance(std::size_t b, std::size_t e, Get get) {
  double mean = 0;
  for (std::size_t k = b; k < e; ++k) mean += get(k);
  mean /= static_cast<double>(e - b);
  double ss = 0;
  for (std::size_t k = b; k < e; ++k) ss += (get(k) - mean) * (get(k) - mean);
  return ss / static_cast<double>(e - b - 1);
}

}  // namespace

std::vector<StaticSegment> find_static_segments(const ImuSamples& s, const StaticDetection& o) {
  std::vector<StaticSegment> out;
  if (s.size() < 10) return out;
  const double dt_s = s.covered_s() / static_cast<double>(s.size());
  const std::size_t w =
      std::max<std::size_t>(kMinWindowSamples, static_cast<std::size_t>(std::lround(o.window_s / dt_s)));
  const std::size_t windows = s.size() / w;
  if (windows < 3) return out;
  // variance[c][k]: channel c (gyro x,y,z, accel x,y,z) over window k.
  std::array<std::vector<double>, 6> variance;
  for (int c = 0; c < 6; ++c) {
    variance[c].resize(windows);
    for (std::size_t k = 0; k < windows; ++k)
      variance[c][k] = window_variance(k * w, (k + 1) * w, [&](std::size_t i) {
        return c < 3 ? s.gyro_b_radps[i][c] : s.accel_b_mps2[i][c - 3];
      });
  }
  // The smallest nonzero step of each channel: its quantum q, whose
  // rounding noise q²/12 floors the reference (a quiet quantized channel
  // has many windows of zero variance, and one step would then count as a turn).
  std::array<double, 6> quantum;
  quantum.fill(0);
  for (std::size_t k = 1; k < s.size(); ++k)
    for (int c = 0; c < 6; ++c) {
      const double step = c < 3 ? std::abs(s.gyro_b_radps[k][c] - s.gyro_b_radps[k - 1][c])
                                : std::abs(s.accel_b_mps2[k][c - 3] - s.accel_b_mps2[k - 1][c - 3]);
      if (step > 0 && (quantum[c] == 0 || step < quantum[c])) quantum[c] = step;
    }
  std::array<double, 6> reference{};
  for (int c = 0; c < 6; ++c) {
    std::vector<double> v = variance[c];
    const auto q = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 5);
    std::nth_element(v.begin(), q, v.end());
    // Floors far below any sensor's resolution (1e-9 rad/s, 1e-8 m/s²), so
    // that a noise-free (synthetic) recording has a reference above zero.
    reference[c] = std::max({*q, quantum[c] * quantum[c] / 12, c < 3 ? 1e-18 : 1e-16});
  }
  // A steady turn (constant rate) keeps the gyro variance at noise: the
  // gyro means tell it apart. Each window's mean must lie near the median of
  // all windows' means, within variance_factor times their robust spread
  // (1.4826 × the median absolute departure; at least a window mean's noise).
  std::array<std::vector<double>, 3> mean;
  std::array<double, 3> centre{}, spread{};
  for (int c = 0; c < 3; ++c) {
    mean[c].resize(windows);
    for (std::size_t k = 0; k < windows; ++k) {
      double sum = 0;
      for (std::size_t i = k * w; i < (k + 1) * w; ++i) sum += s.gyro_b_radps[i][c];
      mean[c][k] = sum / static_cast<double>(w);
    }
    std::vector<double> v = mean[c];
    const auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
    std::nth_element(v.begin(), mid, v.end());
    centre[c] = *mid;
    for (double& x : v) x = std::abs(x - centre[c]);
    std::nth_element(v.begin(), mid, v.end());
    spread[c] = std::max(1.4826 * *mid, std::sqrt(reference[c] / static_cast<double>(w)));
  }
  std::vector<bool> still(windows);
  for (std::size_t k = 0; k < windows; ++k) {
    still[k] = true;
    for (int c = 0; c < 6; ++c) still[k] = still[k] && variance[c][k] <= o.variance_factor * reference[c];
    for (int c = 0; c < 3; ++c)
      still[k] = still[k] && std::abs(mean[c][k] - centre[c]) <= o.variance_factor * spread[c];
  }
  const std::size_t min_windows = static_cast<std::size_t>(std::ceil(o.min_duration_s / (dt_s * w)));
  for (std::size_t k = 0; k < windows;) {
    if (!still[k]) {
      ++k;
      continue;
    }
    std::size_t e = k;
    while (e < windows && still[e]) ++e;
    // Cut one window at each end: the turn may begin or end inside it.
    const std::size_t b = k + 1, last = e - 1;
    if (last > b && last - b >= min_windows) out.push_back({b * w, last * w});
    k = e;
  }
  return out;
}

}  // namespace insmc::calibration
