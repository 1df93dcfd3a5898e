#pragma once
/// The gap metric (issue 7): scale-free, per report group g the log ratio of
/// the observed Σ z² (run_analysis.h) to what the model predicts for it,
///   ℓ_g = ln( Σ z²  /  (Σ E_i/e_i + κ_g Σ (1 − E_i/e_i)) ),
///   G   = sqrt(mean over groups ℓ_g²),
/// E_i the expected square of a term under the actual noise, e_i its
/// normalizer (with the model-error floor), and κ_g the share of the floor's
/// contribution that the model's own null really shows (the truth level's
/// second-order terms and g_s, which the floor stands for): measured once on
/// null truth runs (diagnosis.h) and kept when a candidate changes the model.
/// A candidate's own variance is then compared as itself, not as a multiple
/// of a floor ten times looser than the null (κ ≈ 0.01 in the test-run r
/// groups).
/// G = 0: the data scatter exactly as the model predicts in every group;
/// G = 1: by a factor e^{±1} ≈ 2.7 in power on average. Too much scatter
/// (an unmodelled effect) and too little (a model wider than the data) both
/// count, so a candidate cannot remove the gap by widening everything.
#include <array>
#include <span>

#include "lib/gap/run_analysis.h"

namespace insmc::gap {

using GroupValues = std::array<double, kGroupCount>;

/// κ_g per group: the share of the floor's contribution to Σ z² that the
/// null runs show beyond the actual noise (≥ 0; 1 where the floor adds nothing).
struct NullCalibration {
  GroupValues floor_share{};
  /// From the pooled sums of the null runs under the base model.
  static NullCalibration from_null(const GroupSums& null_sums);
};

/// Mean z² per group (NaN where a group has no terms).
GroupValues group_power(const GroupSums& sums);

/// The calibrated expected mean z² per group (NaN where no terms).
GroupValues expected_power(const GroupSums& sums, const NullCalibration& calibration);

/// ℓ_g (NaN where a group has no terms).
GroupValues log_power_ratio(const GroupSums& sums, const NullCalibration& calibration);

/// G from the ℓ_g present.
double gap_value(const GroupValues& log_ratio);
inline double gap_value(const GroupSums& sums, const NullCalibration& calibration) {
  return gap_value(log_power_ratio(sums, calibration));
}

/// Σ of the runs' sums picked by `runs` (indices into `per_run`).
GroupSums pooled(std::span<const GroupSums> per_run, std::span<const int> runs);

}  // namespace insmc::gap
