// Every candidate's extension of the run model at every grid point.
#include "montecarlo/records/gap/candidates/candidates.h"

#include <gtest/gtest.h>

#include <cmath>

#include "montecarlo/records/runs/model/gaussian_model.h"
#include "montecarlo/records/runs/model/run_analysis.h"
#include "tests/unit/montecarlo/records/runs/test_layout.h"

namespace insmc::gap {
namespace {

using runs::testing::test_layout;
using runs::testing::test_site;

TEST(GapCandidates, EveryGridPointBuildsAConsistentExtension) {
  const runs::Layout l = test_layout(2400.0);
  const runs::RecordSite s = test_site();
  const runs::BaseModel base = make_base_model(l, s, UncertaintyModel{}.variance());
  for (const Candidate& c : candidate_registry()) {
    const LayoutContext ctx{&l, &s, &base, {}};
    const std::vector<int> amplitudes = c.amplitude_indices();
    ASSERT_TRUE(c.grid_size() > 1 || !amplitudes.empty()) << c.name << ": nothing to fit";
    for (int j : amplitudes) {
      // The least-squares fit of an amplitude needs a mean linear in it.
      std::vector<double> theta = c.grid_point(0);
      theta[static_cast<std::size_t>(j)] = 1.0;
      const Eigen::VectorXd one = c.build(ctx, theta).mean;
      theta[static_cast<std::size_t>(j)] = -2.5;
      const Eigen::VectorXd scaled = c.build(ctx, theta).mean;
      ASSERT_EQ(one.size(), static_cast<Eigen::Index>(l.rows.size())) << c.name;
      EXPECT_GT(one.norm(), 0.0) << c.name;
      EXPECT_LE((scaled + 2.5 * one).norm(), 1e-12 * one.norm()) << c.name;
      EXPECT_TRUE(c.build(ctx, c.grid_point(0)).mean_only()) << c.name;
    }
    for (int k : {0, c.grid_size() - 1}) {
      const runs::Extension e = c.build(ctx, c.grid_point(k));
      EXPECT_EQ(e.columns.cols(), e.column_var.size()) << c.name;
      if (e.columns.cols() > 0) {
        EXPECT_EQ(e.columns.rows(), static_cast<Eigen::Index>(l.rows.size())) << c.name;
      }
      if (e.mean.size() > 0) {
        EXPECT_EQ(e.mean.size(), static_cast<Eigen::Index>(l.rows.size())) << c.name;
      }
      if (e.noise_var_add.size() > 0) {
        EXPECT_EQ(e.noise_var_add.size(), static_cast<Eigen::Index>(l.rows.size())) << c.name;
        EXPECT_GE(e.noise_var_add.minCoeff(), 0.0) << c.name;
      }
      EXPECT_GE(e.x_var_add.minCoeff(), 0.0) << c.name;
      const runs::GaussianModel m = combine(base, {&e});
      EXPECT_NO_FATAL_FAILURE(runs::RunAnalyser(l, m)) << c.name;
    }
  }
}

}  // namespace
}  // namespace insmc::gap
