#pragma once
/// Fit of the standard noise terms (lib/noise/noise_terms.h) to a channel's
/// overlapping Allan variance, with intervals and model selection
/// (docs/noise.md §3).
///
/// Method (a generalized method of wavelet moments on the Allan variance):
/// 1. Pilot: each level's estimate ν̂_j taken as ν_j χ²(d_j)/d_j with the
///    equivalent degrees of freedom of the noise type that dominates there,
///    levels independent:
///      ℓ(p) = Σ_j (d_j/2) (ν̂_j/ν_j(p) + ln ν_j(p)),  ν_j(p) = Σ_k p_k A_k(τ_j)  (N.2)
///    minimised over the powers p_k ≥ 0 by iteratively reweighted
///    non-negative least squares (its fixed point is the stationary point).
/// 2. Fit: the levels are correlated (overlapping windows, octave spacing);
///    their covariance S under the pilot model follows from the model
///    (lib/noise/allan_covariance.h, (N.4)), and the powers minimise
///      J(p) = rᵀ S⁻¹ r,  r_j = (ν̂_j − ν_j(p)) / ν̃_j                          (N.5)
///    (non-negative least squares after whitening), twice, the second time
///    weighted under the first fit. T_c by a search in ln T_c.
/// Model selection: backward elimination, taking the simplification whose
/// rise of J (of 2ℓ in the pilot) is furthest below χ²_df at 1 − 2α (a power
/// on its boundary p = 0: ½χ²₀ + ½χ²₁): a term dropped (df 1; 2 for the
/// Gauss–Markov term unless a white rate or random walk remains to take its
/// limit), or the Gauss–Markov term replaced by its limit T_c → 0 (white
/// rate) or T_c → ∞ (random walk) (df 1), so that a random walk is not
/// reported as a Gauss–Markov process with a long T_c.
/// A simplification is taken only if the simpler model still passes the fit
/// test below, so every term the data need stays.
/// Intervals: profile of J, ΔJ ≤ χ²₁ at the confidence (T_c refitted in the
/// profile of the Gauss–Markov σ).
/// Fit test: J = rᵀ S⁻¹ r with S the covariance of the levels under the
/// fitted model itself is χ² with (levels − fitted parameters) degrees of
/// freedom when the model is the process's (GMWM, Guerrier et al. 2013); the
/// model fails when J is above its 1 − α quantile. A model that fails is not
/// the fit: the shortest levels (where a sensor's own filtering and
/// sampling bend the curve away from every standard term) are left out one
/// at a time until a model passes on the rest, and if none does on at least
/// kMinFitLevels levels the fit says so (fits = false).
#include <array>
#include <span>
#include <string>
#include <vector>

#include "lib/noise/allan_variance.h"
#include "lib/noise/noise_terms.h"

namespace insmc::noise {

/// A noise model: the power p = coefficient² of each term (0 = absent).
struct NoiseModel {
  std::array<double, kAllNoiseTerms.size()> power{};
  double correlation_time_s = 0;  ///< T_c of the Gauss–Markov term (0 = absent)

  double& operator[](NoiseTerm t) { return power[static_cast<std::size_t>(t)]; }
  double operator[](NoiseTerm t) const { return power[static_cast<std::size_t>(t)]; }
  /// σ²(τ) of the model.
  double avar(double tau_s) const;
  /// The power-law α of the term that contributes most to σ²(τ).
  PowerLaw dominant_type(double tau_s) const;
  /// (N.1) of the model: Var(ȳ_B − ȳ_A) for averages over tau_s at starts lag_s apart.
  double mean_difference_variance(double tau_s, double lag_s) const;
};

/// A fitted term: its coefficient √p in SI (lib/noise/noise_terms.h), the
/// profile-likelihood interval, and the likelihood-ratio statistic of
/// dropping it from the selected model.
struct TermFit {
  NoiseTerm term{};
  double value_si = 0, lower_si = 0, upper_si = 0;
  double drop_statistic = 0;  ///< 2Δℓ when the term is removed
};

struct NoiseFitOptions {
  double selection_alpha = 0.01;  ///< significance of the likelihood-ratio test that keeps a term
  double confidence = 0.95;       ///< of the profile intervals
  /// Terms the fit may use (default: all six).
  std::vector<NoiseTerm> allowed{kAllNoiseTerms.begin(), kAllNoiseTerms.end()};
};

struct NoiseFit {
  NoiseModel model;
  std::vector<TermFit> terms;  ///< the selected terms, in kAllNoiseTerms order
  double correlation_time_lower_s = 0, correlation_time_upper_s = 0;  ///< if Gauss–Markov is selected
  std::vector<double> edf;     ///< per level, under the fitted model
  double objective = 0;        ///< (N.5) at the fit
  /// Terms tried and dropped, with their statistic (for the report).
  std::vector<TermFit> dropped;
  /// The fit test over the levels [first_level, end): J under the model's
  /// own covariance, its degrees of freedom and p-value.
  double fit_statistic = 0, fit_dof = 0, fit_p_value = 1;
  bool fits = true;
  std::size_t first_level = 0;  ///< the levels before it are outside every model that passes
};

/// The fewest levels a fit is tried on when the shortest are left out.
inline constexpr std::size_t kMinFitLevels = 6;

/// Fits the levels (at least 2); throws std::invalid_argument on fewer.
NoiseFit fit_noise(std::span<const AllanLevel> levels, const NoiseFitOptions& options = {});

}  // namespace insmc::noise
