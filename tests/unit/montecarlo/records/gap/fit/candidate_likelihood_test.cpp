// A candidate's injected likelihood evaluation (montecarlo/records/gap/fit/candidate_likelihood.h)
// on runs drawn from the run model with the candidate at a known value:
// the evaluation is the model's own likelihood, and the maximum-likelihood
// fit (likelihood_fit.h) finds the value within its interval.
#include "montecarlo/records/gap/fit/candidate_likelihood.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>
#include <stdexcept>
#include <string>

#include "lib/uncertainty/uncertainty_model.h"
#include "lib/units/units.h"
#include "montecarlo/records/gap/fit/likelihood_fit.h"
#include "montecarlo/records/runs/model/likelihood.h"
#include "tests/unit/montecarlo/records/runs/test_layout.h"

namespace insmc::gap {
namespace {

runs::Layout layout(double end_s) { return runs::testing::test_layout(end_s); }

const gap::Candidate& candidate(const std::string& name) {
  for (const gap::Candidate& c : gap::candidate_registry())
    if (c.name == name) return c;
  throw std::runtime_error("no candidate " + name);
}

/// `runs` draws y = μ + H c + e from the model with `bounds` at scale `s`.
runs::PreparedRuns drawn_runs(int runs, double s, std::uint64_t seed) {
  runs::PreparedRuns p;
  p.site.filter_interval_s = 10.0;
  p.site.dv_pulse_mps = 0.1 * kFtpsToMps;
  p.x_var = UncertaintyModel{}.variance();
  const runs::Layout l = layout(2700.0);
  const int L = p.layout_index(l);
  const runs::BaseModel base = p.base_of(0);
  gap::LayoutContext ctx{&p.layouts[0], &p.site, &base, {}};
  const double theta[] = {s};
  const runs::Extension e = candidate("bounds").build(ctx, theta);
  const runs::GaussianModel m = runs::combine(base, {&e});
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> normal;
  for (int r = 0; r < runs; ++r) {
    // Columns the layout does not see (a scheme's measurement errors on runs
    // without it) draw nothing: the runs do not depend on the catalogue's width.
    Eigen::VectorXd c = Eigen::VectorXd::Zero(m.H.cols());
    for (Eigen::Index j = 0; j < c.size(); ++j)
      if (m.H.col(j).squaredNorm() > 0) c[j] = std::sqrt(m.prior_var[j]) * normal(rng);
    const Eigen::VectorXd noise =
        m.noise_var.cwiseSqrt().cwiseProduct(Eigen::VectorXd::NullaryExpr(m.H.rows(), [&] { return normal(rng); }));
    const Eigen::VectorXd y = m.mean + m.H * c + noise;
    p.runs.push_back({r, l, std::vector<double>(y.data(), y.data() + y.size()), 2700.0});
    p.layout_of.push_back(L);
  }
  return p;
}

TEST(GapCandidateLikelihood, IsTheCombinedModelsLikelihoodAndFitsTheDrawnValue) {
  const double truth = 3.0;
  const runs::PreparedRuns p = drawn_runs(16, truth, 5);
  const std::vector<std::vector<runs::Extension>> selected(p.layouts.size());
  const gap::Candidate& c = candidate("bounds");
  const RunLogLikelihoods evaluate = candidate_evaluation(p, c, selected);

  // One evaluation: one model build and factorization per layout.
  const auto t0 = std::chrono::steady_clock::now();
  const double at[] = {2.0};
  const std::vector<double> ll = evaluate(at);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf("one evaluation: %.3f s (%zu rows, %d runs)\n", seconds, p.layouts[0].rows.size(),
              static_cast<int>(p.runs.size()));

  const runs::BaseModel base = p.base_of(0);
  gap::LayoutContext ctx{&p.layouts[0], &p.site, &base, {}};
  const runs::Extension e = c.build(ctx, at);
  const runs::RunLikelihood direct(runs::combine(base, {&e}));
  const runs::RunLikelihood null_model(runs::combine(base, {}));
  const std::vector<double> null = null_log_likelihoods(p, selected);
  ASSERT_EQ(ll.size(), p.runs.size());
  for (std::size_t r = 0; r < p.runs.size(); ++r) {
    EXPECT_DOUBLE_EQ(ll[r], direct.log_likelihood(run_values(p.runs[r])));
    EXPECT_DOUBLE_EQ(null[r], null_model.log_likelihood(run_values(p.runs[r])));
  }

  // Physical limits of the prior scale: from narrower than Table 3.1 to ×1000.
  LikelihoodLattice lattice({{"scale", 0.1, 1000.0, 1.0}}, evaluate, static_cast<int>(p.runs.size()));
  std::vector<int> all(p.runs.size());
  for (std::size_t r = 0; r < all.size(); ++r) all[r] = static_cast<int>(r);
  const LikelihoodFit fit = fit_likelihood(lattice, all);
  const ProfileInterval& ci = fit.parameters[0].ci95;
  std::printf("scale %.3g (95 %%: %.3g..%.3g), %d evaluations\n", fit.parameters[0].value_si, ci.lower_si, ci.upper_si,
              fit.evaluations);
  EXPECT_FALSE(fit.at_limit());
  EXPECT_LE(ci.lower_si, truth);
  EXPECT_GE(ci.upper_si, truth);
  // Scale 1 is the null model: the held-out runs prefer the drawn scale.
  const CrossValidation cv = cross_validate(lattice, null);
  EXPECT_GT(cv.gain, 0.0);
  std::printf("held-out gain %.1f, %d more evaluations\n", cv.gain, cv.evaluations);
}

}  // namespace
}  // namespace insmc::gap
