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

TEST(GapCandidates, SwayCountsAtTheSitesPulseWhateverCountingCameBefore) {
  // sway's counting replaces one another extension set (quantization's,
  // selected first), at every grid point: where no axis cycles it is the
  // base model's counting, where some do its own.
  const runs::Layout l = test_layout(2400.0);
  const runs::RecordSite s = test_site();
  ASSERT_GT(s.dv_pulse_mps, 0.0);
  const runs::BaseModel base = make_base_model(l, s, UncertaintyModel{}.variance());
  const Candidate* sway = nullptr;
  const Candidate* quantization = nullptr;
  for (const Candidate& c : candidate_registry()) {
    if (c.name == "sway") sway = &c;
    if (c.name == "quantization") quantization = &c;
  }
  ASSERT_TRUE(sway && quantization);
  const LayoutContext ctx{&l, &s, &base, {}};
  const runs::Extension other = quantization->build(ctx, quantization->grid_point(quantization->grid_size() - 1));
  ASSERT_TRUE(other.counting.has_value());
  int as_base = 0, own = 0;
  for (int k = 0; k < sway->grid_size(); ++k) {
    const runs::Extension e = sway->build(ctx, sway->grid_point(k));
    ASSERT_TRUE(e.counting.has_value()) << "grid point " << k;
    const runs::GaussianModel alone = combine(base, {&e});
    const runs::GaussianModel after = combine(base, {&other, &e});
    EXPECT_EQ(after.noise_var, alone.noise_var) << "grid point " << k;
    EXPECT_EQ(after.H, alone.H) << "grid point " << k;
    if (e.counting->columns == base.counting.columns && e.counting->noise_var == base.counting.noise_var) ++as_base;
    else ++own;
  }
  // The grid reaches both: sways below half a pulse and above it.
  EXPECT_GT(as_base, 0);
  EXPECT_GT(own, 0);
}

}  // namespace
}  // namespace insmc::gap
