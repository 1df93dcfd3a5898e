#pragma once
// The check shared by the statistical tests that compare the Monte Carlo
// with the exact covariance: by the central limit theorem the mean of n
// values of r² is normal with variance Var(r²)/n, Var(r²) exact from the
// study's linear map (StudyMap::predicted_var_r2), so the check
// |mean r² − E r²| ≤ z sqrt(Var(r²)/n) has the false-alarm rate of z.
#include <boost/math/distributions/normal.hpp>
#include <cmath>
#include <fmt/format.h>
#include <string>

#include "montecarlo/study/engine/engine.h"

namespace insmc::mc::testing {

struct R2Check {
  double deviation, bound;
  bool pass() const { return std::fabs(deviation) <= bound; }
};

inline R2Check r2_check(const mc::OutputStats& s, const mc::StudyMap& exact, std::size_t o, double z) {
  const double n = static_cast<double>(s.count());
  const double e_r2 = exact.predicted_rms()[o] * exact.predicted_rms()[o];
  return {s.sum_squares() / n - e_r2, z * std::sqrt(exact.predicted_var_r2()[o] / n)};
}

/// Power of the two-sided check when the statistic is N(shift, sd_alt²) and
/// it rejects outside ±z sd_null.
inline double two_sided_power(double shift, double sd_null, double sd_alt, double z) {
  const boost::math::normal nd;
  return boost::math::cdf(nd, (-z * sd_null - shift) / sd_alt) +
         boost::math::cdf(boost::math::complement(nd, (z * sd_null - shift) / sd_alt));
}

inline std::string describe(const mc::StudyLayout& l, std::size_t o) {
  const mc::OutputSpec& s = l.outputs[o];
  return fmt::format("scheme {}, system {}, t = {} min, {}", to_string(s.scheme), system_number(s.system),
                     std::lround(l.times_s[static_cast<std::size_t>(s.time_index)] / 60), to_string(s.axis));
}

}  // namespace insmc::mc::testing
