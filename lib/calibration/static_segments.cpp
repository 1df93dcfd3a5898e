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
  const std::size_t w = std::max<std::size_t>(5, static_cast<std::size_t>(std::lround(o.window_s / dt_s)));
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
  std::array<double, 6> reference{};
  for (int c = 0; c < 6; ++c) {
    std::vector<double> v = variance[c];
    const auto q = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 5);
    std::nth_element(v.begin(), q, v.end());
    // Floors far below any sensor's resolution (1e-9 rad/s, 1e-8 m/s²), so
    // that a noise-free (synthetic) recording has a reference above zero.
    reference[c] = std::max(*q, c < 3 ? 1e-18 : 1e-16);
  }
  std::vector<bool> still(windows);
  for (std::size_t k = 0; k < windows; ++k) {
    still[k] = true;
    for (int c = 0; c < 6; ++c) still[k] = still[k] && variance[c][k] <= o.variance_factor * reference[c];
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
