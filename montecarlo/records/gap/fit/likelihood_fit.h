#pragma once
/// Maximum-likelihood fit of a candidate's non-amplitude parameters over a
/// set of runs, without grid edges. The least-G fit (candidate_fit.h,
/// docs/gap-method.md §4) searches capped log grids and can only say "at the edge";
/// here each parameter is searched on a log scale between its physical
/// limits, and a fit at a limit is a statement about the physics.
///
/// The objective of a subset of runs is the sum of their exact Gaussian
/// log-likelihoods (model/likelihood.h), cached per run on a fine lattice
/// (likelihood_lattice.h) so that the full-data fit, the two folds of the
/// cross-validation and the profile intervals share every model build.
///
/// Search: a coarse pass at ×10 steps over the whole range, then golden
/// section on the lattice around the best, down to the lattice step. Several
/// parameters: coordinate ascent, alternate 1-D searches (the coarse pass in
/// the first round, local searches after) until a round changes nothing.
/// Intervals: profile likelihood, where the maximum over the other
/// parameters falls 0.5 (68 %) and 1.92 (95 %) below the maximum, each side
/// (Wilks: twice the drop is χ²₁ with 1 and 3.84 at those levels).
#include <array>
#include <span>
#include <string>
#include <vector>

#include "montecarlo/records/gap/fit/likelihood_lattice.h"

namespace insmc::gap {

/// Where the profile log-likelihood stays within a drop of its maximum. An
/// end that reaches a physical limit is open there (the data do not close it).
struct ProfileInterval {
  double lower_si = 0.0;
  double upper_si = 0.0;
  bool open_lower = false;
  bool open_upper = false;
};

struct ParameterFit {
  std::string name;
  double value_si = 0.0;
  bool at_lower = false;  ///< the maximum sits at the lower physical limit
  bool at_upper = false;  ///< … at the upper one
  ProfileInterval ci68;   ///< drop 0.5
  ProfileInterval ci95;   ///< drop 1.92
};

struct LikelihoodFit {
  std::vector<ParameterFit> parameters;
  std::vector<int> index;       ///< lattice point of the maximum
  double log_likelihood = 0.0;  ///< at the maximum, summed over the fitted runs
  int rounds = 0;               ///< coordinate-ascent rounds
  int evaluations = 0;          ///< model evaluations this fit added (the rest came from the memo)
  bool at_limit() const;
};

/// Drops of the profile log-likelihood that bound the 68 % and 95 % intervals.
inline constexpr double kDrop68 = 0.5;
inline constexpr double kDrop95 = 1.92;
/// Coordinate ascent stops after this many rounds even if a parameter still
/// moves (a ridge the lattice follows a step at a time).
inline constexpr int kMaxAscentRounds = 6;

/// How coordinate ascent starts from the parameters' start values: a coarse
/// pass over each whole range first, or local searches only (a warm start
/// from values already fitted, e.g. a pair's from each member's own fit).
enum class Search { kCoarse, kLocal };

/// The maximum of Σ_{r ∈ runs} log p_r over the lattice, with profile
/// intervals when `intervals`, from the lattice point `start` (empty: the
/// parameters' start values).
LikelihoodFit fit_likelihood(LikelihoodLattice& lattice, std::span<const int> runs, bool intervals = true,
                             Search search = Search::kCoarse, std::span<const int> start = {});

/// The held-out log-likelihood gain of a 2-fold cross-validation: runs
/// alternate between halves in file order; each half is fitted and the
/// other half's log-likelihood at that fit, less its log-likelihood under
/// the null model (no candidate, `null_per_run`), is summed over both folds.
/// Positive: the candidate predicts runs it was not fitted to better than
/// the model without it (docs/gap-method.md §4, the ranking by held-out runs).
struct CrossValidation {
  double gain = 0.0;
  /// Fold f is fitted on half f (runs f, f + 2, …) and scored on the other half.
  std::array<double, 2> fold_gain{};
  std::array<std::vector<double>, 2> fold_values;  ///< the parameters fitted on half f (SI)
  int evaluations = 0;
};
CrossValidation cross_validate(LikelihoodLattice& lattice, std::span<const double> null_per_run);
/// The same with a lattice per fold: fold f is fitted and scored on
/// `folds[f]`, a model whose held parts (the amplitudes of a deterministic
/// signature, likelihood_parameters()) were fitted on half f too, so that
/// nothing of the held-out half enters its own prediction. Both may be one lattice.
CrossValidation cross_validate(std::array<LikelihoodLattice*, 2> folds, std::span<const double> null_per_run,
                               Search search = Search::kCoarse, std::span<const int> start = {});

}  // namespace insmc::gap
