// A scheme defined outside the library (here, in this test) is one
// definition and one registration: the registry, the option parser, the
// paper and linear maps, the truth level and the Monte Carlo engine take it
// without any other change. The scheme is 5.1.1 without its integrator
// ramp (5.3): Û2 at point 2 (5.2), then the realignment. Its maps must be
// 5.1.1's without the Û3 columns, its truth runs must agree with its linear
// level by the bound of every built-in scheme (scheme_case.h), and the
// Monte Carlo must reproduce its exact covariance. The registry's own
// entries are checked too: the report's schemes in report order, and every
// measurement-error group a scheme names is one of the catalogue's
// scheme_errors, each claimed, and acting only in the schemes that claim it.
#include <gtest/gtest.h>

#include <boost/math/distributions/normal.hpp>
#include <algorithm>
#include <cmath>
#include <set>
#include <string>

#include "lib/common/input_error.h"
#include "lib/compensation/compensation_maps.h"
#include "lib/compensation/schemes/scheme_definition.h"
#include "lib/uncertainty/catalogue.h"
#include "montecarlo/study/engine/engine.h"
#include "tests/unit/lib/compensation/scheme_case.h"

namespace insmc {
namespace {

const SchemeDefinition kStepOnly{
    .name = "test-step-only",
    .equations = "(5.2), then the realignment of (5.4)",
    .realigns = true,
    .uses_test_run = true,
    .measurement_error_groups = {"realignment_azimuth_error"},
    .position_map = [](const SchemeMapContext& c, ExtendedMap& e) { scheme_terms::add_u2_step(c, e); },
    .truth_action =
        [](const TruthSchemeContext& c, TruthOptions& o, UncertaintyVector&) {
          o.accel_compensation.step_mps2 = -c.model.gravity_mps2 * c.estimates.u2;
        },
};

const Scheme kStepOnlyScheme = register_scheme(kStepOnly);

TEST(SchemeRegistry, TheReportsSchemesComeFirstInReportOrder) {
  const std::vector<std::string> report = {"none", "5.1.1", "5.1.2", "combined", "5.2", "5.3", "5.4"};
  const std::vector<Scheme> named = {Scheme::kNone, Scheme::k5_1_1, Scheme::k5_1_2, Scheme::kCombined,
                                     Scheme::k5_2,  Scheme::k5_3,   Scheme::k5_4};
  const std::vector<Scheme> all = all_schemes();
  ASSERT_EQ(all.size(), report.size() + 1);  // and the test's own
  for (std::size_t i = 0; i < report.size(); ++i) {
    EXPECT_EQ(to_string(named[i]), report[i]);
    EXPECT_EQ(all[i], named[i]);
    EXPECT_EQ(parse_scheme(report[i]), named[i]);
  }
  for (Scheme s : all) {
    EXPECT_NE(s.definition().position_map, nullptr) << to_string(s);
    EXPECT_NE(s.definition().truth_action, nullptr) << to_string(s);
    EXPECT_FALSE(s.definition().equations.empty()) << to_string(s);
  }
  EXPECT_THROW(register_scheme(kStepOnly), std::logic_error);
  EXPECT_THROW(parse_scheme("5.5"), InputError);
}

TEST(SchemeRegistry, EveryMeasurementErrorGroupIsASchemeErrorClaimedAndActingOnlyWhereClaimed) {
  const std::vector<std::string> groups = uncertainty_groups();
  std::set<int> claimed;
  for (Scheme s : all_schemes())
    for (std::string_view group : s.definition().measurement_error_groups) {
      ASSERT_NE(std::find(groups.begin(), groups.end(), std::string(group)), groups.end()) << group;
      for (int i : select_uncertainties(group)) {
        EXPECT_TRUE(is_scheme_error(catalogue()[static_cast<std::size_t>(i)])) << group;
        claimed.insert(i);
      }
    }
  for (int i = 0; i < uncertainty_slot::kDim; ++i) EXPECT_EQ(claimed.count(i), is_scheme_error(catalogue()[static_cast<std::size_t>(i)]) ? 1u : 0u) << catalogue()[static_cast<std::size_t>(i)].name;
  const std::vector<double> t = {600.0, 2520.0, 5040.0};
  for (Scheme s : all_schemes()) {
    std::set<int> own;
    for (std::string_view group : s.definition().measurement_error_groups)
      for (int i : select_uncertainties(group)) own.insert(i);
    for (System system : {System::kTheodolite, System::kGyrocompass})
      for (Fidelity f : {Fidelity::kPaper, Fidelity::kLinear}) {
        const SchemeMaps maps = scheme_position_maps(s, system, f, ModelOptions{}, TestRunOptions{}, t);
        for (int i = 0; i < uncertainty_slot::kDim; ++i) {
          if (!is_scheme_error(catalogue()[static_cast<std::size_t>(i)])) continue;
          double acts = 0;
          for (const ExtendedMap& e : maps.position) acts += e.col(i).norm();
          // System 2 has no y estimate of the drift (5.15c), so its ε4y acts
          // nowhere, and no theodolite to re-sight.
          const bool inert =
              system == System::kGyrocompass && (i == uncertainty_slot::kAlignDriftError + 1 || i == uncertainty_slot::kRealignAzimuthError);
          EXPECT_EQ(acts > 0, own.count(i) == 1 && !inert) << to_string(s) << " " << catalogue()[static_cast<std::size_t>(i)].name;
        }
      }
  }
}

TEST(TestOnlyScheme, IsParsedAndCarriesItsTraits) {
  EXPECT_EQ(parse_scheme("test-step-only"), kStepOnlyScheme);
  EXPECT_EQ(all_schemes().back(), kStepOnlyScheme);
  EXPECT_EQ(clock_of(kStepOnlyScheme), "realignment");
  EXPECT_DOUBLE_EQ(ready_time_s(kStepOnlyScheme, 900.0, 600.0), 1500.0);
}

TEST(TestOnlyScheme, MapsAre511WithoutTheIntegratorRamp) {
  const std::vector<double> t = {600.0, 2520.0, 3780.0, 5040.0};
  for (System s : {System::kTheodolite, System::kGyrocompass})
    for (Fidelity f : {Fidelity::kPaper, Fidelity::kLinear}) {
      const SchemeMaps mine = scheme_position_maps(kStepOnlyScheme, s, f, ModelOptions{}, TestRunOptions{}, t);
      const SchemeMaps full = scheme_position_maps(Scheme::k5_1_1, s, f, ModelOptions{}, TestRunOptions{}, t);
      EXPECT_EQ(mine.ready_time_s, full.ready_time_s);
      for (std::size_t k = 0; k < t.size(); ++k) {
        ExtendedMap expected = full.position[k];
        ASSERT_GT(expected.middleCols<3>(z_slot::kU3).norm(), 0.0);
        expected.middleCols<3>(z_slot::kU3).setZero();
        EXPECT_EQ(mine.position[k], expected) << "t = " << t[k];
      }
    }
}

TEST(TestOnlyScheme, TruthAgreesWithTheLinearLevelRunByRun) {
  for (System s : {System::kTheodolite, System::kGyrocompass}) {
    const testing::Case c = testing::make_case(s);
    for (std::uint64_t seed : {1u, 2u}) {
      const testing::Agreement a = testing::truth_linear_agreement(c, kStepOnlyScheme, seed);
      EXPECT_LE(a.worst_excess_m, 0.0) << "system " << system_number(s) << " seed " << seed << ": worst "
                                       << a.worst_m << " m";
      EXPECT_GT(a.worst_m, 0.0);
    }
    // The ramp it leaves out matters at the truth level too: the same sample's
    // flight after 5.1.1 differs from it by more than the agreement bound
    // (1 % + 1 m) at 84 min.
    TruthOptions o = testing::continuous(s);
    o.filter_interval_s = c.test.filter_interval_s;
    const TruthSchemeSetup setup(o, c.test, c.estimators);
    TruthSchemeSample sample;
    sample.x = testing::within_bounds(1);
    sample.realigned_x = sample.x;
    const std::vector<double> t = {84 * 60.0};
    const Vec3 mine = run_truth_scheme(kStepOnlyScheme, setup, sample, t).flight.position_error_ap_m[0];
    const Vec3 full = run_truth_scheme(Scheme::k5_1_1, setup, sample, t).flight.position_error_ap_m[0];
    EXPECT_GT((mine - full).norm(), 0.01 * full.norm() + 1.0) << "system " << system_number(s);
  }
}

TEST(TestOnlyScheme, TheMonteCarloReproducesItsExactCovariance) {
  // Continuous measurements: the position error is exactly linear in x and
  // the realignment's draws, so mean r² over n samples is normal about the
  // exact E r² with variance Var(r²)/n (StudyMap::predicted_var_r2). Two-sided
  // α = 1e-6 over the 24 outputs (Bonferroni).
  mc::StudyConfig config;
  config.schemes = {kStepOnlyScheme};
  config.fidelity = Fidelity::kLinear;
  config.with_grid = false;
  config.test.dv_pulse_mps = 0.0;
  config.test.position_resolution_m = 0.0;
  config.samples = 20000;
  config.seed = 0x5c4e'3e00ULL;
  config.threads = 1;
  const mc::StudyLayout layout = mc::make_layout(config);
  const mc::StudyMap map(config, layout);
  const mc::StudyAccumulator acc = mc::run_blocks(config, map, 0, mc::block_count(config.samples));
  const double z = boost::math::quantile(
      boost::math::complement(boost::math::normal(), 1e-6 / (2.0 * static_cast<double>(layout.outputs.size()))));
  ASSERT_EQ(layout.outputs.size(), 24u);
  for (std::size_t o = 0; o < layout.outputs.size(); ++o) {
    const mc::OutputStats& s = acc.outputs()[o];
    const double n = static_cast<double>(s.count()), e_r2 = map.predicted_rms()[o] * map.predicted_rms()[o];
    ASSERT_GT(e_r2, 0.0);
    EXPECT_LE(std::fabs(s.sum_squares() / n - e_r2), z * std::sqrt(map.predicted_var_r2()[o] / n)) << "output " << o;
  }
}

}  // namespace
}  // namespace insmc
