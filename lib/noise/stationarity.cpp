#include "lib/noise/stationarity.h"

#include <algorithm>
#include <boost/math/distributions/chi_squared.hpp>
#include <cmath>

namespace insmc::noise {
namespace {

/// Mean of y over [from, to) counting only kept samples; NaN if none.
double kept_mean(std::span<const double> y, std::span<const Segment> kept, std::size_t from, std::size_t to) {
  double sum = 0;
  std::size_t count = 0;
  for (const Segment& s : kept) {
    const std::size_t a = std::max(from, s.begin), b = std::min(to, s.end);
    for (std::size_t k = a; k < b; ++k) sum += y[k], ++count;
  }
  return count ? sum / static_cast<double>(count) : std::nan("");
}

}  // namespace

std::vector<Segment> after_first_part(std::span<const Segment> runs, std::span<const Segment> kept, double dt_s,
                                      double first_part_s) {
  std::vector<Segment> out;
  const auto skip = static_cast<std::size_t>(std::llround(first_part_s / dt_s));
  for (const Segment& s : kept) {
    for (const Segment& r : runs)
      if (s.begin >= r.begin && s.end <= r.end) {
        const std::size_t from = std::max(s.begin, r.begin + skip);
        if (s.end > from) out.push_back({from, s.end});
      }
  }
  return out;
}

StationarityTest test_first_part(std::span<const double> y, double dt_s, std::span<const Segment> runs,
                                 std::span<const Segment> kept, const NoiseModel& rest_model, double first_part_s,
                                 double alpha) {
  StationarityTest t;
  t.first_part_s = first_part_s;
  t.block_s = first_part_s / 6;
  const auto part = static_cast<std::size_t>(std::llround(first_part_s / dt_s));
  const auto block = static_cast<std::size_t>(std::llround(t.block_s / dt_s));
  if (block < 1) return t;
  const double var = rest_model.mean_difference_variance(t.block_s, t.first_part_s - t.block_s);  // (N.1)
  if (!(var > 0)) return t;
  t.expected_sd = std::sqrt(var);
  double sum_d = 0;
  for (const Segment& r : runs) {
    if (r.size() < 2 * part) continue;
    const double a = kept_mean(y, kept, r.begin, r.begin + block);
    const double b = kept_mean(y, kept, r.begin + part - block, r.begin + part);
    if (!std::isfinite(a) || !std::isfinite(b)) continue;
    const double d = b - a;
    sum_d += d;
    t.statistic += d * d / var;
    ++t.runs;
  }
  if (t.runs == 0) return t;
  t.tested = true;
  t.mean_change = sum_d / static_cast<double>(t.runs);
  t.p_value = boost::math::cdf(boost::math::complement(boost::math::chi_squared(static_cast<double>(t.runs)), t.statistic));
  t.stationary = t.p_value >= alpha;
  return t;
}

}  // namespace insmc::noise
