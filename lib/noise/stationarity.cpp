#include "lib/noise/stationarity.h"

#include <algorithm>
#include <boost/math/distributions/chi_squared.hpp>
#include <cmath>

namespace insmc::noise {
namespace {

/// The kept stretches of [from, to), as sample index ranges.
std::vector<Segment> kept_within(std::span<const Segment> kept, std::size_t from, std::size_t to) {
  std::vector<Segment> out;
  for (const Segment& s : kept) {
    const std::size_t a = std::max(from, s.begin), b = std::min(to, s.end);
    if (b > a) out.push_back({a, b});
  }
  return out;
}

/// Mean of y over the stretches, and the points of θ that make it:
/// ȳ = Σ_s (θ(e_s) − θ(b_s)) / T with T the stretches' total length.
double add_mean(std::span<const double> y, const std::vector<Segment>& parts, double dt_s, double sign,
                std::vector<std::pair<double, double>>& points) {
  double sum = 0;
  std::size_t count = 0;
  for (const Segment& s : parts) {
    for (std::size_t k = s.begin; k < s.end; ++k) sum += y[k];
    count += s.size();
  }
  const double length_s = static_cast<double>(count) * dt_s;
  for (const Segment& s : parts) {
    points.push_back({static_cast<double>(s.end) * dt_s, sign / length_s});
    points.push_back({static_cast<double>(s.begin) * dt_s, -sign / length_s});
  }
  return sum / static_cast<double>(count);
}

/// (N.6): the variance of Σ c_i θ(t_i) under the model, for coefficients
/// with Σ c_i = 0 and Σ c_i t_i = 0 (points as (t_i [s], c_i)).
double combination_variance(const NoiseModel& model, std::span<const std::pair<double, double>> points) {
  double v = 0;
  for (const auto& [ti, ci] : points)
    for (const auto& [tj, cj] : points) {
      double d = 0;
      for (NoiseTerm t : kAllNoiseTerms)
        if (model[t] > 0) d += model[t] * structure_shape(t, ti - tj, model.correlation_time_s);
      v += ci * cj * d;
    }
  return -0.5 * v;  // (N.6)
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
  const auto part = static_cast<std::size_t>(std::llround(first_part_s / dt_s));
  if (part < 1) return t;
  double sum_d = 0, sum_var = 0;
  for (const Segment& r : runs) {
    if (r.size() < 2 * part) continue;
    const std::vector<Segment> first = kept_within(kept, r.begin, r.begin + part);
    const std::vector<Segment> rest = kept_within(kept, r.begin + part, r.end);
    if (first.empty() || rest.empty()) continue;
    std::vector<std::pair<double, double>> points;
    const double d = add_mean(y, first, dt_s, 1, points) - add_mean(y, rest, dt_s, -1, points);
    const double var = combination_variance(rest_model, points);
    if (!(var > 0)) continue;
    sum_d += d;
    sum_var += var;
    t.statistic += d * d / var;
    ++t.runs;
  }
  if (t.runs == 0) return t;
  t.tested = true;
  t.mean_change = sum_d / static_cast<double>(t.runs);
  t.expected_sd = std::sqrt(sum_var / static_cast<double>(t.runs));
  t.p_value = boost::math::cdf(boost::math::complement(boost::math::chi_squared(static_cast<double>(t.runs)), t.statistic));
  t.stationary = t.p_value >= alpha;
  return t;
}

}  // namespace insmc::noise
