#include "lib/gap/gap_metric.h"

#include <cmath>
#include <limits>

namespace insmc::gap {

GroupValues group_power(const GroupSums& sums) {
  GroupValues p;
  for (int g = 0; g < kGroupCount; ++g)
    p[g] = sums.count[g] > 0 ? sums.z2[g] / sums.count[g] : std::numeric_limits<double>::quiet_NaN();
  return p;
}

GroupValues log_power_ratio(const GroupSums& sums, const GroupValues& reference_power) {
  const GroupValues p = group_power(sums);
  GroupValues l;
  for (int g = 0; g < kGroupCount; ++g) {
    // A floor keeps a group that is fitted exactly from counting as infinite.
    l[g] = std::isfinite(p[g]) && reference_power[g] > 0
               ? std::log(std::max(p[g], 1e-12) / reference_power[g])
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
