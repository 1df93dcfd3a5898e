#include "lib/noise/allan_variance.h"

#include <algorithm>
#include <boost/math/distributions/chi_squared.hpp>
#include <cmath>

namespace insmc::noise {

std::vector<AllanLevel> overlapping_allan(std::span<const double> y, double dt_s, std::span<const Segment> segments,
                                          std::size_t max_cluster) {
  std::size_t longest = 0;
  for (const Segment& s : segments) longest = std::max(longest, s.size());
  // θ per segment, from the segment's own mean removed (the mean cancels in
  // the second difference; removing it keeps the running sum small).
  std::vector<std::vector<long double>> theta;
  theta.reserve(segments.size());
  for (const Segment& s : segments) {
    std::vector<long double> t(s.size() + 1, 0.0L);
    if (s.size() >= 3) {
      long double mean = 0;
      for (std::size_t k = s.begin; k < s.end; ++k) mean += y[k];
      mean /= static_cast<long double>(s.size());
      for (std::size_t k = 0; k < s.size(); ++k) t[k + 1] = t[k] + (y[s.begin + k] - mean) * dt_s;
    }
    theta.push_back(std::move(t));
  }
  std::vector<AllanLevel> out;
  for (std::size_t m = 1; 3 * m <= longest && m <= max_cluster; m *= 2) {
    AllanLevel level;
    level.cluster = m;
    level.tau_s = static_cast<double>(m) * dt_s;
    long double sum = 0;
    for (std::size_t i = 0; i < segments.size(); ++i) {
      const std::size_t n = segments[i].size();
      if (n < 3 || 2 * m >= n + 1) continue;
      const std::vector<long double>& t = theta[i];
      // (C.4): windows k = 0 .. N − 2m, over the N + 1 phase points of the segment.
      const std::size_t windows = n + 1 - 2 * m;
      for (std::size_t k = 0; k < windows; ++k) {
        const long double d = t[k + 2 * m] - 2 * t[k + m] + t[k];
        sum += d * d;
      }
      level.windows += windows;
      level.segment_samples.push_back(n);
    }
    if (level.windows == 0) continue;
    level.avar = static_cast<double>(sum / (2.0L * level.tau_s * level.tau_s * static_cast<long double>(level.windows)));
    out.push_back(std::move(level));
  }
  return out;
}

double allan_edf(std::size_t phase_points, std::size_t m, PowerLaw type) {
  const double N = static_cast<double>(phase_points), M = static_cast<double>(m);
  double edf = 1.0;
  switch (type) {
    case PowerLaw::kWhitePhase: edf = (N + 1) * (N - 2 * M) / (2 * (N - M)); break;
    case PowerLaw::kFlickerPhase:
      edf = std::exp(std::sqrt(std::max(0.0, std::log((N - 1) / (2 * M)) * std::log((2 * M + 1) * (N - 1) / 4))));
      break;
    case PowerLaw::kWhiteRate:
      edf = (3 * (N - 1) / (2 * M) - 2 * (N - 2) / N) * 4 * M * M / (4 * M * M + 5);
      break;
    case PowerLaw::kFlickerRate:
      edf = m == 1 ? 2 * (N - 2) / (2.3 * N - 4.9) : 5 * N * N / (4 * M * (N + 3 * M));
      break;
    case PowerLaw::kRandomWalkRate:
      edf = (N - 2) / M * ((N - 1) * (N - 1) - 3 * M * (N - 1) + 4 * M * M) / ((N - 3) * (N - 3));
      break;
  }
  // The simple formulas are fits; they are not meant below one degree of
  // freedom, nor above the number of windows.
  return std::clamp(std::isfinite(edf) ? edf : 1.0, 1.0, std::max(1.0, N - 2 * M));
}

double allan_edf(const AllanLevel& level, PowerLaw type) {
  double edf = 0;
  for (std::size_t n : level.segment_samples) edf += allan_edf(n + 1, level.cluster, type);
  return std::max(1.0, edf);
}

DeviationInterval adev_interval(double avar, double edf, double confidence) {
  const boost::math::chi_squared chi(edf);
  const double a = (1 - confidence) / 2;
  const double hi_q = boost::math::quantile(chi, 1 - a), lo_q = boost::math::quantile(chi, a);
  return {std::sqrt(avar * edf / hi_q), std::sqrt(avar * edf / lo_q)};
}

}  // namespace insmc::noise
