#include "montecarlo/records/gap/metric/gap_metric.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace insmc::gap {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// Σ over the scatter groups of a coherent group of a per-group value.
template <class F>
double over_members(int c, const F& f) {
  double sum = 0.0;
  for (int g = 0; g < runs::kGroupCount; ++g)
    if (runs::coherent_group_of(g) == c) sum += f(g);
  return sum;
}

double expected_sum(const runs::GroupSums& s, const NullCalibration& cal, int g) {
  return s.expected[g] + cal.floor_share[g] * s.floor[g];
}

}  // namespace

NullCalibration NullCalibration::from_null(const RunSet& null) {
  NullCalibration cal;
  std::vector<int> all(static_cast<std::size_t>(null.size()));
  std::iota(all.begin(), all.end(), 0);
  const Pooled p = pool(null, all);
  const runs::GroupSums& s = p.power;
  for (int g = 0; g < runs::kGroupCount; ++g)
    cal.floor_share[g] = s.floor[g] > 1e-9 * s.count[g] ? std::max(0.0, (s.z2[g] - s.expected[g]) / s.floor[g]) : 1.0;
  const double n = null.size();
  for (int c = 0; c < runs::kCoherentCount; ++c) {
    // The mean inner product of two different null runs, over the floor one
    // run contributes: the share of the floor that all runs have in common.
    const double pairs = n > 1 ? null.distinct_pair_sum(c) / (n * (n - 1)) : 0.0;
    const double floor = over_members(c, [&](int k) { return s.floor[k]; }) / std::max(n, 1.0);
    cal.systematic[static_cast<std::size_t>(c)] = floor > 1e-9 ? std::max(0.0, pairs / floor) : 0.0;
  }
  return cal;
}

GroupValues group_power(const runs::GroupSums& sums) {
  GroupValues p;
  for (int g = 0; g < runs::kGroupCount; ++g) p[g] = sums.count[g] > 0 ? sums.z2[g] / sums.count[g] : kNaN;
  return p;
}

GroupValues expected_power(const runs::GroupSums& sums, const NullCalibration& cal) {
  GroupValues p;
  for (int g = 0; g < runs::kGroupCount; ++g) p[g] = sums.count[g] > 0 ? expected_sum(sums, cal, g) / sums.count[g] : kNaN;
  return p;
}

CoherentValues coherent_power(const Pooled& p) {
  CoherentValues out;
  for (int c = 0; c < runs::kCoherentCount; ++c) {
    const double count = over_members(c, [&](int g) { return p.power.count[g]; });
    out[static_cast<std::size_t>(c)] = count > 0 ? p.coherent[static_cast<std::size_t>(c)] / count : kNaN;
  }
  return out;
}

CoherentValues expected_coherent_power(const Pooled& p, const NullCalibration& cal, CoherentReference reference) {
  CoherentValues out;
  const double m = p.runs;
  for (int c = 0; c < runs::kCoherentCount; ++c) {
    const double count = over_members(c, [&](int g) { return p.power.count[g]; });
    // The runs' own scatter as observed: only what they share beyond
    // independence is compared, so a random effect, which raises every
    // run's scatter but nothing common, leaves these groups alone.
    // For significance, runs that scatter less than the model (an
    // assumption pessimistic) are compared with the model's own scatter: a
    // signature they share counts when it is as large as what the model
    // lets independent runs scatter, not when it is merely larger than
    // their tiny scatter (runs of a perfect sensor are alike to the last
    // digit and share nothing that matters).
    const double observed_scatter = over_members(c, [&](int g) { return p.power.z2[g]; }) / m;
    const double model_scatter = over_members(c, [&](int g) { return expected_sum(p.power, cal, g); }) / m;
    const double scatter = reference == CoherentReference::kAtLeastModelScatter
                               ? std::max(observed_scatter, model_scatter)
                               : observed_scatter;
    const double common = (m - 1) / m * cal.systematic[static_cast<std::size_t>(c)] *
                          over_members(c, [&](int g) { return p.power.floor[g]; });
    out[static_cast<std::size_t>(c)] = count > 0 && m > 0 ? (scatter + common) / count : kNaN;
  }
  return out;
}

LogRatios log_ratios(const Pooled& p, const NullCalibration& cal, CoherentReference reference) {
  LogRatios l;
  for (int g = 0; g < runs::kGroupCount; ++g) {
    // The model expects between the linear level's own scatter (no model
    // error) and that plus the floor's share the null shows (the truth
    // level's second-order terms): data anywhere in that band agree with it.
    const double upper = expected_sum(p.power, cal, g), lower = p.power.expected[g];
    // A floor keeps a group that is fitted exactly from counting as infinite.
    const double observed = std::max(p.power.z2[g], 1e-12 * p.power.count[g]);
    if (!(p.power.count[g] > 0 && upper > 0)) {
      l.scatter[g] = kNaN;
    } else if (observed > upper) {
      l.scatter[g] = std::log(observed / upper);
    } else if (lower > 0 && observed < lower) {
      l.scatter[g] = std::log(observed / lower);
    } else {
      l.scatter[g] = 0.0;
    }
  }
  const CoherentValues observed = coherent_power(p), expected = expected_coherent_power(p, cal, reference);
  for (int c = 0; c < runs::kCoherentCount; ++c) {
    const auto k = static_cast<std::size_t>(c);
    l.coherent[k] = std::isfinite(observed[k]) && expected[k] > 0 ? std::log(std::max(observed[k], expected[k]) / expected[k])
                                                                  : kNaN;
  }
  return l;
}

double gap_value(const LogRatios& l) {
  double sum = 0.0;
  int n = 0;
  for (double v : l.scatter)
    if (std::isfinite(v)) sum += v * v, ++n;
  for (double v : l.coherent)
    if (std::isfinite(v)) sum += v * v, ++n;
  return n > 0 ? std::sqrt(sum / n) : 0.0;
}

SignedGap signed_gap(const LogRatios& l) {
  double above = 0.0, below = 0.0;
  int n = 0;
  const auto add = [&](double v) {
    if (!std::isfinite(v)) return;
    ++n;
    (v > 0 ? above : below) += v * v;
  };
  for (double v : l.scatter) add(v);
  for (double v : l.coherent) add(v);
  return n > 0 ? SignedGap{std::sqrt(above / n), std::sqrt(below / n)} : SignedGap{};
}

}  // namespace insmc::gap
