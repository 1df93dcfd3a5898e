// The schemes' measurement errors in the scheme maps (compensation_maps.h):
// each acts only in the scheme that relies on it; the resets' errors follow
// (5.8)'s cos ω_s t' and sin ω_s t' / ω_s at the paper level and the
// numerically integrated Schuler ODE at the linear level; 5.4's ω_ie E4
// enters as the measured torquer commands do (5.15).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "lib/compensation/compensation_maps.h"
#include "lib/uncertainty/catalogue.h"

namespace insmc {
namespace {

std::vector<double> minutes(std::initializer_list<double> m) {
  std::vector<double> out;
  for (double v : m) out.push_back(60.0 * v);
  return out;
}

TEST(SchemeErrors, EachActsOnlyInTheSchemeThatReliesOnIt) {
  const std::vector<double> t = minutes({10, 42, 63, 84});
  for (System s : {System::kTheodolite, System::kGyrocompass})
    for (Fidelity f : {Fidelity::kPaper, Fidelity::kLinear})
      for (Scheme scheme : all_schemes()) {
        const SchemeMaps maps = scheme_position_maps(scheme, s, f, ModelOptions{}, TestRunOptions{}, t);
        for (const ExtendedMap& e : maps.position) {
          const double drift = e.middleCols<3>(uncertainty_slot::kAlignDriftError).norm();
          const double reset = e.middleCols<6>(uncertainty_slot::kResetPositionError).norm();
          EXPECT_EQ(drift > 0, scheme == Scheme::k5_4) << to_string(scheme);
          EXPECT_EQ(reset > 0, resets_at_test_end(scheme)) << to_string(scheme);
        }
      }
}

TEST(SchemeErrors, ResetErrorsFollowEquation58AndTheSchulerOde) {
  const ModelOptions m;
  const double ws = m.schuler_radps();
  const std::vector<double> t = minutes({1, 21, 42, 63, 84, 90});
  for (Scheme scheme : {Scheme::k5_2, Scheme::k5_3}) {
    const SchemeMaps paper = scheme_position_maps(scheme, System::kTheodolite, Fidelity::kPaper, m, TestRunOptions{}, t);
    const SchemeMaps linear = scheme_position_maps(scheme, System::kTheodolite, Fidelity::kLinear, m, TestRunOptions{}, t);
    for (std::size_t k = 0; k < t.size(); ++k) {
      const Mat3 r_paper = paper.position[k].middleCols<3>(uncertainty_slot::kResetPositionError);
      const Mat3 v_paper = paper.position[k].middleCols<3>(uncertainty_slot::kResetVelocityError);
      EXPECT_TRUE(r_paper.isApprox(std::cos(ws * t[k]) * Mat3::Identity(), 1e-15));
      EXPECT_TRUE(v_paper.isApprox(std::sin(ws * t[k]) / ws * Mat3::Identity(), 1e-15));
      // RK4 with 2 s steps over at most 90 min: far below a millimetre per metre or per m/s.
      EXPECT_LT((linear.position[k].middleCols<3>(uncertainty_slot::kResetPositionError) - r_paper).norm(), 1e-6);
      EXPECT_LT((linear.position[k].middleCols<3>(uncertainty_slot::kResetVelocityError) - v_paper).norm(), 1e-3);
    }
  }
}

TEST(SchemeErrors, TheDriftEstimateErrorEntersAsTheTorquerCommands) {
  const std::vector<double> t = minutes({42, 84});
  for (System s : {System::kTheodolite, System::kGyrocompass})
    for (Fidelity f : {Fidelity::kPaper, Fidelity::kLinear}) {
      const SchemeMaps maps = scheme_position_maps(Scheme::k5_4, s, f, ModelOptions{}, TestRunOptions{}, t);
      for (const ExtendedMap& e : maps.position) {
        EXPECT_EQ(e.middleCols<3>(uncertainty_slot::kAlignDriftError), e.middleCols<3>(z_slot::kTorquerCommands));
        // (5.15c): system 2 estimates no y drift, so its ε4y acts nowhere.
        if (s == System::kGyrocompass) {
          EXPECT_EQ(e.col(uncertainty_slot::kAlignDriftError + 1).norm(), 0.0);
        }
      }
    }
}

TEST(SchemeErrors, TheGroupSelectsTheTenAndNothingElse) {
  const std::vector<int> all = select_uncertainties(kSchemeErrorsGroup);
  ASSERT_EQ(all.size(), 10u);
  for (int i : all) EXPECT_TRUE(is_scheme_error(catalogue()[i]));
  EXPECT_EQ(select_uncertainties("alignment_drift_error").size(), 3u);
  EXPECT_EQ(select_uncertainties("realignment_azimuth_error"), std::vector<int>{uncertainty_slot::kRealignAzimuthError});
  EXPECT_EQ(uncertainty_groups().back(), kSchemeErrorsGroup);
}

TEST(SchemeErrors, AreTheCatalogueGroupsListedNotASlotRange) {
  // Each listed group names entries of the catalogue, and an entry is a
  // scheme error exactly when its group is listed: Table 3.1's entries,
  // whatever their slot, never are.
  for (std::string_view group : kSchemeErrorGroups) EXPECT_FALSE(select_uncertainties(group).empty()) << group;
  int count = 0;
  for (const UncertaintySpec& spec : catalogue()) {
    const bool listed =
        std::find(kSchemeErrorGroups.begin(), kSchemeErrorGroups.end(), spec.group) != kSchemeErrorGroups.end();
    EXPECT_EQ(is_scheme_error(spec), listed) << spec.name;
    count += listed ? 1 : 0;
  }
  EXPECT_EQ(count, 10);
  // A Table 3.1 entry placed after the scheme errors would stay one of
  // Table 3.1's: the group decides, not the index.
  UncertaintySpec moved = catalogue()[uncertainty_slot::kAltitudeError];
  moved.index = uncertainty_slot::kDim - 1;
  EXPECT_FALSE(is_scheme_error(moved));
}

}  // namespace
}  // namespace insmc
