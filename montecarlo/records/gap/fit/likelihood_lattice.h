#pragma once
/// The memo of a maximum-likelihood fit (likelihood_fit.h): each parameter
/// on a fine log lattice between its physical limits, and every run's
/// log-likelihood at each lattice point evaluated once. One evaluation is a
/// model build per layout (~0.1 s), while the fits that share it — the full
/// data, the two folds of the cross-validation, the profile intervals — only
/// sum cached per-run values over their own subsets of runs.
#include <functional>
#include <map>
#include <span>
#include <string>
#include <vector>

namespace insmc::gap {

/// A parameter searched on a log scale between physical limits (SI, 0 < lower ≤ upper).
struct FitParameter {
  std::string name;
  double lower_si = 0.0;
  double upper_si = 0.0;
  double start_si = 0.0;  ///< where coordinate ascent holds it before its first search
};

/// The per-run log-likelihoods of ALL runs at parameter values (SI, in
/// parameter order). Injected: the lattice does not know how models are built.
using RunLogLikelihoods = std::function<std::vector<double>(std::span<const double> params)>;

/// Lattice step of the memo: fits agree to 5 % in the parameters, far inside
/// their statistical intervals.
inline constexpr double kLatticeStep = 1.05;

class LikelihoodLattice {
 public:
  /// `runs`: how many values `evaluate` returns. The lattice of each
  /// parameter runs from lower to upper in equal log steps of at most `step`.
  LikelihoodLattice(std::vector<FitParameter> parameters, RunLogLikelihoods evaluate, int runs,
                    double step = kLatticeStep);

  int dimensions() const { return static_cast<int>(parameters_.size()); }
  int runs() const { return runs_; }
  const FitParameter& parameter(int p) const { return parameters_[static_cast<std::size_t>(p)]; }
  /// Index of the last lattice point of parameter p (its upper limit).
  int last(int p) const { return last_[static_cast<std::size_t>(p)]; }
  /// Lattice points per factor 10 of parameter p (the coarse search's step).
  int per_decade(int p) const;
  /// Value (SI) of lattice point k of parameter p, and the nearest point to a value.
  double value(int p, int k) const;
  int nearest(int p, double value_si) const;
  std::vector<double> values(std::span<const int> index) const;

  /// Every run's log-likelihood at a lattice point, evaluated on first use
  /// (NaN, a failed build, counts as −∞).
  const std::vector<double>& per_run(std::span<const int> index);
  /// The log-likelihood of the subset `runs` (indices, repeats allowed) at a lattice point.
  double sum(std::span<const int> index, std::span<const int> runs);

  /// Evaluations made so far (distinct lattice points).
  int evaluations() const { return static_cast<int>(cache_.size()); }

 private:
  std::vector<FitParameter> parameters_;
  RunLogLikelihoods evaluate_;
  int runs_ = 0;
  std::vector<int> last_;
  std::vector<double> log_step_;  // per parameter: ln of its (equal) lattice step
  std::map<std::vector<int>, std::vector<double>> cache_;
};

}  // namespace insmc::gap
