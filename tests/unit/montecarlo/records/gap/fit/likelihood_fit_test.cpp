// Maximum-likelihood fit on a memoized log lattice (montecarlo/records/gap/fit/likelihood_fit.h)
// with synthetic injected evaluations whose maxima and intervals are known.
#include "montecarlo/records/gap/fit/likelihood_fit.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <numeric>
#include <random>

namespace insmc::gap {
namespace {

/// m runs of n iid N(0, σ²) values; the parameter is σ². Run j's
/// log-likelihood −½ Σ (ln 2πσ² + x²/σ²) depends on its sum of squares only.
struct VarianceProblem {
  std::vector<double> sum_squares;  // per run
  int n = 0;
  int calls = 0;

  VarianceProblem(int runs, int n_per_run, double variance, std::uint64_t seed) : n(n_per_run) {
    std::mt19937_64 rng(seed);
    std::normal_distribution<double> normal(0.0, std::sqrt(variance));
    for (int j = 0; j < runs; ++j) {
      double s = 0.0;
      for (int i = 0; i < n; ++i) s += std::pow(normal(rng), 2);
      sum_squares.push_back(s);
    }
  }
  std::vector<double> per_run(double variance) const {
    std::vector<double> v;
    for (double s : sum_squares) v.push_back(-0.5 * (n * std::log(2.0 * std::numbers::pi * variance) + s / variance));
    return v;
  }
  RunLogLikelihoods evaluation() {
    return [this](std::span<const double> p) {
      ++calls;
      return per_run(p[0]);
    };
  }
  int runs() const { return static_cast<int>(sum_squares.size()); }
  double mle(std::span<const int> subset) const {
    double s = 0.0;
    for (int j : subset) s += sum_squares[static_cast<std::size_t>(j)];
    return s / (n * static_cast<double>(subset.size()));
  }
};

std::vector<int> all_runs(int m) {
  std::vector<int> r(static_cast<std::size_t>(m));
  std::iota(r.begin(), r.end(), 0);
  return r;
}

/// P(X < c) for X ~ Binomial(trials, p).
double binomial_below(int c, int trials, double p) {
  double total = 0.0;
  for (int k = 0; k < c; ++k)
    total += std::exp(std::lgamma(trials + 1.0) - std::lgamma(k + 1.0) - std::lgamma(trials - k + 1.0) +
                      k * std::log(p) + (trials - k) * std::log1p(-p));
  return total;
}

TEST(GapLikelihoodFit, VarianceScaleMaximumAndProfileCoverage) {
  const double truth = 2.3;  // off the lattice
  const int seeds = 100;
  int covered = 0;
  for (int seed = 0; seed < seeds; ++seed) {
    VarianceProblem problem(10, 20, truth, 1000 + static_cast<std::uint64_t>(seed));
    LikelihoodLattice lattice({{"variance", 1e-4, 1e4, 1.0}}, problem.evaluation(), problem.runs());
    const std::vector<int> runs = all_runs(problem.runs());
    const LikelihoodFit fit = fit_likelihood(lattice, runs);
    ASSERT_EQ(fit.parameters.size(), 1u);
    const ParameterFit& q = fit.parameters[0];
    // The lattice point of the maximum is a neighbour of the MLE.
    EXPECT_LE(std::abs(std::log(q.value_si / problem.mle(runs))), std::log(kLatticeStep)) << "seed " << seed;
    EXPECT_FALSE(fit.at_limit());
    EXPECT_LT(q.ci68.lower_si, q.value_si);
    EXPECT_GT(q.ci68.upper_si, q.value_si);
    EXPECT_LT(q.ci95.lower_si, q.ci68.lower_si);
    EXPECT_GT(q.ci95.upper_si, q.ci68.upper_si);
    EXPECT_FALSE(q.ci95.open_lower || q.ci95.open_upper);
    EXPECT_EQ(fit.evaluations, problem.calls);
    if (q.ci95.lower_si <= truth && truth <= q.ci95.upper_si) ++covered;
  }
  // A 95 % interval covers in Binomial(100, 0.95) seeds: the least count a
  // correct interval falls below with probability ≤ 2 %.
  int required = 0;
  while (binomial_below(required + 1, seeds, 0.95) <= 0.02) ++required;
  EXPECT_EQ(required, 90);
  EXPECT_GE(covered, required);
  std::printf("95 %% profile intervals covering the truth: %d of %d\n", covered, seeds);
}

TEST(GapLikelihoodFit, OptimumBeyondTheUpperLimitIsHeldThereAndFlagged) {
  VarianceProblem problem(10, 20, 50.0, 5);
  LikelihoodLattice lattice({{"variance", 1e-3, 10.0, 1.0}}, problem.evaluation(), problem.runs());
  const LikelihoodFit fit = fit_likelihood(lattice, all_runs(problem.runs()));
  const ParameterFit& q = fit.parameters[0];
  EXPECT_DOUBLE_EQ(q.value_si, 10.0);
  EXPECT_TRUE(q.at_upper);
  EXPECT_FALSE(q.at_lower);
  EXPECT_TRUE(fit.at_limit());
  EXPECT_TRUE(q.ci95.open_upper);
  EXPECT_DOUBLE_EQ(q.ci95.upper_si, 10.0);
  EXPECT_TRUE(q.ci68.open_upper);
  EXPECT_FALSE(q.ci95.open_lower);
  EXPECT_LT(q.ci95.lower_si, 10.0);
}

/// Run j's log-likelihood −½ w_j dᵀ A d, d = (ln p₁ − ln t₁, ln p₂ − ln t₂).
struct QuadraticProblem {
  double t1, t2, a11, a12, a22;
  std::vector<double> weight;
  int calls = 0;
  RunLogLikelihoods evaluation() {
    return [this](std::span<const double> p) {
      ++calls;
      const double d1 = std::log(p[0] / t1), d2 = std::log(p[1] / t2);
      const double q = a11 * d1 * d1 + 2.0 * a12 * d1 * d2 + a22 * d2 * d2;
      std::vector<double> v;
      for (double w : weight) v.push_back(-0.5 * w * q);
      return v;
    };
  }
  /// Profile 95 % half-width of ln p₁ and ln p₂: ½ W d²/(A⁻¹)_pp = 1.92.
  double half_width(int p) const {
    const double W = std::accumulate(weight.begin(), weight.end(), 0.0);
    const double det = a11 * a22 - a12 * a12;
    const double inverse = (p == 0 ? a22 : a11) / det;
    return std::sqrt(2.0 * kDrop95 * inverse / W);
  }
};

void expect_quadratic_fit(QuadraticProblem& problem, double tolerance_steps) {
  const std::vector<FitParameter> parameters{{"p1", 1e-6, 1.0, 1e-3}, {"p2", 10.0, 1e5, 1e3}};
  LikelihoodLattice lattice(parameters, problem.evaluation(), static_cast<int>(problem.weight.size()));
  const LikelihoodFit fit = fit_likelihood(lattice, all_runs(static_cast<int>(problem.weight.size())));
  const double step = std::log(kLatticeStep);
  EXPECT_LE(std::abs(std::log(fit.parameters[0].value_si / problem.t1)), tolerance_steps * step);
  EXPECT_LE(std::abs(std::log(fit.parameters[1].value_si / problem.t2)), tolerance_steps * step);
  EXPECT_FALSE(fit.at_limit());
  for (int p = 0; p < 2; ++p) {
    const ProfileInterval& ci = fit.parameters[static_cast<std::size_t>(p)].ci95;
    const double centre = std::log(p == 0 ? problem.t1 : problem.t2), w = problem.half_width(p);
    EXPECT_NEAR(std::log(ci.lower_si), centre - w, tolerance_steps * step) << "parameter " << p;
    EXPECT_NEAR(std::log(ci.upper_si), centre + w, tolerance_steps * step) << "parameter " << p;
  }
  EXPECT_EQ(fit.evaluations, problem.calls);
  LikelihoodLattice fresh(parameters, problem.evaluation(), static_cast<int>(problem.weight.size()));
  const int point_only = fit_likelihood(fresh, all_runs(static_cast<int>(problem.weight.size())), false).evaluations;
  std::printf("without intervals %d evaluations; ", point_only);
  std::printf("maximum (%.4g, %.4g), truth (%.4g, %.4g), %d rounds, %d evaluations\n", fit.parameters[0].value_si,
              fit.parameters[1].value_si, problem.t1, problem.t2, fit.rounds, fit.evaluations);
}

TEST(GapLikelihoodFit, SeparableTwoParameterMaximumByCoordinateAscent) {
  QuadraticProblem problem{3.7e-3, 420.0, 1.0, 0.0, 0.5, {0.5, 1.0, 1.5, 2.0}};
  expect_quadratic_fit(problem, 1.0);
}

TEST(GapLikelihoodFit, CorrelatedTwoParameterMaximumByCoordinateAscent) {
  // Correlation 0.6: each round of coordinate ascent closes only part of the
  // way along the ridge, so several rounds are needed.
  QuadraticProblem problem{3.7e-3, 420.0, 1.0, 0.6 * std::sqrt(0.5), 0.5, {0.5, 1.0, 1.5, 2.0}};
  expect_quadratic_fit(problem, 2.0);
}

TEST(GapLikelihoodFit, ALocalSearchFromAFarStartFindsTheSameMaximum) {
  // A warm start (a pair from its members' fits) searches locally only: the
  // doubling steps still climb six decades to the maximum, and the folds of
  // a cross-validation may start from the fit on all runs.
  VarianceProblem problem(20, 20, 2.3, 19);
  LikelihoodLattice lattice({{"variance", 1e-4, 1e4, 1e-3}}, problem.evaluation(), problem.runs());
  const std::vector<int> all = all_runs(problem.runs());
  const LikelihoodFit local = fit_likelihood(lattice, all, false, Search::kLocal);
  EXPECT_LE(std::abs(std::log(local.parameters[0].value_si / problem.mle(all))), std::log(kLatticeStep));
  const std::vector<double> null(static_cast<std::size_t>(problem.runs()), 0.0);
  const CrossValidation from_fit = cross_validate({&lattice, &lattice}, null, Search::kLocal, local.index);
  const CrossValidation coarse = cross_validate(lattice, null);
  EXPECT_NEAR(from_fit.gain, coarse.gain, 1e-9 * std::abs(coarse.gain));
}

TEST(GapLikelihoodFit, SubsetFitsReuseTheMemo) {
  VarianceProblem problem(20, 20, 2.3, 17);
  LikelihoodLattice lattice({{"variance", 1e-4, 1e4, 1.0}}, problem.evaluation(), problem.runs());
  const LikelihoodFit full = fit_likelihood(lattice, all_runs(problem.runs()));
  // The coarse pass and most of the bisection are shared with any subset.
  std::vector<int> first_half;
  for (int r = 0; r < problem.runs(); r += 2) first_half.push_back(r);
  const LikelihoodFit half = fit_likelihood(lattice, first_half, false);
  EXPECT_LE(half.evaluations, 6) << "full fit took " << full.evaluations;
  std::printf("full fit %d evaluations, half %d more\n", full.evaluations, half.evaluations);
  EXPECT_LT(half.evaluations, full.evaluations / 4);
  EXPECT_LE(std::abs(std::log(half.parameters[0].value_si / problem.mle(first_half))), std::log(kLatticeStep));
  EXPECT_EQ(lattice.evaluations(), problem.calls);
}

TEST(GapLikelihoodFit, CrossValidationGainsWhereTheNullIsWrong) {
  // Null model: σ² = 1. Data of σ² = 4: the candidate predicts held-out runs
  // better; data of σ² = 1: it cannot (the fit to one half only adds noise).
  for (const double truth : {4.0, 1.0}) {
    VarianceProblem problem(20, 20, truth, 23);
    LikelihoodLattice lattice({{"variance", 1e-4, 1e4, 1.0}}, problem.evaluation(), problem.runs());
    const std::vector<double> null = problem.per_run(1.0);
    const CrossValidation cv = cross_validate(lattice, null);
    EXPECT_DOUBLE_EQ(cv.gain, cv.fold_gain[0] + cv.fold_gain[1]);
    ASSERT_EQ(cv.fold_values[0].size(), 1u);
    // Each fold's fit is the MLE of its training half (even runs, odd runs).
    std::vector<int> even, odd;
    for (int r = 0; r < problem.runs(); ++r) (r % 2 == 0 ? even : odd).push_back(r);
    EXPECT_LE(std::abs(std::log(cv.fold_values[0][0] / problem.mle(even))), std::log(kLatticeStep));
    EXPECT_LE(std::abs(std::log(cv.fold_values[1][0] / problem.mle(odd))), std::log(kLatticeStep));
    if (truth > 1.0)
      EXPECT_GT(cv.gain, 50.0);  // ≈ ½ N (σ² − 1 − ln σ²) ≈ 320 for N = 400 values
    else
      EXPECT_LT(cv.gain, 5.0);
    EXPECT_EQ(cv.evaluations, problem.calls);
  }
}

}  // namespace
}  // namespace insmc::gap
