#include "lib/gap/gap_metric.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace insmc::gap {

NullCalibration NullCalibration::from_null(const GroupSums& s) {
  NullCalibration c;
  for (int g = 0; g < kGroupCount; ++g)
    c.floor_share[g] = s.floor[g] > 1e-9 * s.count[g] ? std::max(0.0, (s.z2[g] - s.expected[g]) / s.floor[g]) : 1.0;
  return c;
}

GroupValues group_power(const GroupSums& sums) {
  GroupValues p;
  for (int g = 0; g < kGroupCount; ++g)
    p[g] = sums.count[g] > 0 ? sums.z2[g] / sums.count[g] : std::numeric_limits<double>::quiet_NaN();
  return p;
}

namespace {

/// The calibrated expected Σ z².
double expected_sum(const GroupSums& s, const NullCalibration& c, int g) {
  return s.expected[g] + c.floor_share[g] * s.floor[g];
}

}  // namespace

GroupValues expected_power(const GroupSums& sums, const NullCalibration& calibration) {
  GroupValues p;
  for (int g = 0; g < kGroupCount; ++g)
    p[g] = sums.count[g] > 0 ? expected_sum(sums, calibration, g) / sums.count[g]
                             : std::numeric_limits<double>::quiet_NaN();
  return p;
}

GroupValues log_power_ratio(const GroupSums& sums, const NullCalibration& calibration) {
  GroupValues l;
  for (int g = 0; g < kGroupCount; ++g) {
    const double expected = expected_sum(sums, calibration, g);
    // A floor keeps a group that is fitted exactly from counting as infinite.
    l[g] = sums.count[g] > 0 && expected > 0
               ? std::log(std::max(sums.z2[g], 1e-12 * sums.count[g]) / expected)
               : std::numeric_limits<double>::quiet_NaN();
  }
  return l;
}

double gap_value(const GroupValues& l) {
  double sum = 0.0;
  int n = 0;
  for (double v : l)
    if (std::isfinite(v)) sum += v * v, ++n;
  return n > 0 ? std::sqrt(sum / n) : 0.0;
}

GroupSums pooled(std::span<const GroupSums> per_run, std::span<const int> runs) {
  GroupSums s;
  for (int r : runs) s += per_run[static_cast<std::size_t>(r)];
  return s;
}

}  // namespace insmc::gap
