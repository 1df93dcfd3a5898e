#pragma once
/// The gap metric (issue 7): scale-free, per report group g the ratio of the
/// observed mean normalized square (run_analysis.h) to the one the model
/// gives on data drawn from itself, m0_g (1 for an exact linear-Gaussian
/// model; measured by null calibration, gap_diagnosis.h, because the real
/// null — the model with its pulses and its nonlinear terms — is not
/// exactly linear-Gaussian):
///   ℓ_g = ln(Σ_runs Σ z² / Σ_runs n  /  m0_g),
///   G   = sqrt(mean over groups ℓ_g²).
/// G = 0: the data scatter exactly as the model predicts in every group;
/// G = 1: by a factor e^{±1} ≈ 2.7 in power on average. Too much scatter
/// (an unmodelled effect) and too little (a model wider than the data) both
/// count, so a candidate cannot remove the gap by widening everything.
#include <array>
#include <span>

#include "lib/gap/run_analysis.h"

namespace insmc::gap {

using GroupValues = std::array<double, kGroupCount>;

/// Mean z² per group (NaN where a group has no terms).
GroupValues group_power(const GroupSums& sums);

/// ℓ_g (NaN where either side has no terms).
GroupValues log_power_ratio(const GroupSums& sums, const GroupValues& reference_power);

/// G from the ℓ_g present.
double gap_value(const GroupValues& log_ratio);
inline double gap_value(const GroupSums& sums, const GroupValues& reference_power) {
  return gap_value(log_power_ratio(sums, reference_power));
}

/// Σ of the runs' sums picked by `runs` (indices into `per_run`).
GroupSums pooled(std::span<const GroupSums> per_run, std::span<const int> runs);

}  // namespace insmc::gap
