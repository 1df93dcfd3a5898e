#pragma once
/// The gap metric (docs/gap-method.md): scale-free, one log ratio per group of what
/// the data show to what the model predicts for them, and their RMS.
///
/// Scatter groups g (layout.h: axis × stage × window), over the runs' terms i:
///   U_g = Σ E_i/e_i + κ_g Σ (1 − E_i/e_i),   L_g = Σ E_i/e_i,
///   ℓ_g = ln(Σ z² / U_g) above U_g, ln(Σ z² / L_g) below L_g, 0 between,
/// E_i the expected square of a term under the actual noise, e_i its
/// normalizer (with the model-error floor), κ_g the share of the floor's
/// contribution that the model's own null really shows (the truth level's
/// second-order terms and g_s, which the floor stands for). The floor is an
/// allowance, not a prediction: data of the linear level (no second-order
/// terms) scatter at L_g, truth-level data at U_g, and both agree with the
/// model; only scatter beyond the band is a disagreement.
///
/// Coherent groups c (what every run shares): with m runs,
///   C_c = (1/m) Σ_keys (Σ_runs z)²  =  m |mean z|²,
///   E[C_c] = (1/m) Σ_runs |z_run|²  (the runs' own scatter, as observed;
///            for significance the model's, (1/m) U_c with U_c the U_g of
///            its members, when that is more: CoherentReference)
///            + (m − 1)/m λ_c Σ_runs Σ (1 − E_i/e_i),
///   ℓ_c = ln( max(C_c, E[C_c]) / E[C_c] ),
/// λ_c the systematic share of the floor the null shows in common (the
/// second-order terms have a sign). Independent runs share nothing beyond
/// that whatever their scatter, so a random effect leaves these groups
/// alone; a design or site effect (the same signature μ in every run)
/// raises C_c by (m − 1)|μ|², where it adds |μ|² once to the scatter
/// groups. One-sided: runs that share less than independent runs carry no
/// signature, only sampling scatter.
///
/// G = sqrt(mean over the groups present of ℓ²). G = 0: the data scatter
/// and share exactly what the model predicts; G = 1: off by a factor e^{±1}
/// ≈ 2.7 in power on average. Too much scatter (an unmodelled effect) and
/// too little (a model wider than the data) both count, so a candidate
/// cannot remove a gap by widening everything. κ and λ are measured once on
/// null truth runs (diagnosis.h) and kept when a candidate changes the
/// model: a candidate's own variance is compared as itself, not as a
/// multiple of a floor ten times looser than the null (κ ≈ 0.01 in the
/// test-run r groups).
#include <array>
#include <span>

#include "montecarlo/records/gap/metric/run_set.h"

namespace insmc::gap {

using GroupValues = std::array<double, runs::kGroupCount>;

struct NullCalibration {
  GroupValues floor_share{};    ///< κ_g ≥ 0 (1 where the floor adds nothing)
  CoherentValues systematic{};  ///< λ_c ≥ 0
  /// From the null runs under the base model.
  static NullCalibration from_null(const RunSet& null);
};

/// ℓ of the scatter groups and of the coherent groups (NaN where no terms).
struct LogRatios {
  GroupValues scatter{};
  CoherentValues coherent{};
};

/// What a coherent group's shared power is read against (E[C_c] above).
enum class CoherentReference {
  /// The runs' own scatter as observed. Comparing candidates: a candidate
  /// that only widens the model's scatter then cannot explain a signature
  /// the runs share.
  kRunsScatter,
  /// The larger of the runs' scatter and the model's. The significance of
  /// an unmodelled effect (observed and null files alike): runs far below
  /// the model's scatter (a perfect sensor, alike to the last digit) share
  /// nothing the model would notice.
  kAtLeastModelScatter,
};

/// Mean z² per scatter group (NaN where a group has no terms).
GroupValues group_power(const runs::GroupSums& sums);
/// The calibrated expected mean z² per scatter group.
GroupValues expected_power(const runs::GroupSums& sums, const NullCalibration& calibration);
/// C_c / m and its calibrated expectation / m per coherent group.
CoherentValues coherent_power(const Pooled& pooled);
CoherentValues expected_coherent_power(const Pooled& pooled, const NullCalibration& calibration,
                                       CoherentReference reference = CoherentReference::kRunsScatter);

LogRatios log_ratios(const Pooled& pooled, const NullCalibration& calibration,
                     CoherentReference reference = CoherentReference::kRunsScatter);

/// G from the ℓ present.
double gap_value(const LogRatios& l);
inline double gap_value(const Pooled& pooled, const NullCalibration& calibration) {
  return gap_value(log_ratios(pooled, calibration));
}
inline double gap_value(const RunSet& set, std::span<const int> runs, const NullCalibration& calibration) {
  return gap_value(pool(set, runs), calibration);
}

/// G split by the direction of each group's disagreement, over the same
/// groups present: G² = G₊² + G₋², G₊ from the groups with ℓ > 0 (more
/// scatter or more in common than the model: something unmodelled), G₋ from
/// those with ℓ < 0 (less than the model: an assumption pessimistic, e.g. a
/// declared pulse weight coarser than the data show, priors wider than the
/// system). The significance of an unmodelled effect is one-sided, on G₊;
/// G₋ is a finding of its own (docs/gap-method.md §2).
struct SignedGap {
  double unmodelled = 0.0;   ///< G₊
  double pessimistic = 0.0;  ///< G₋
};
SignedGap signed_gap(const LogRatios& l);

}  // namespace insmc::gap
