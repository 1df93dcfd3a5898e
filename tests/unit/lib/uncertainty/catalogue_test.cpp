#include "lib/uncertainty/catalogue.h"

#include <gtest/gtest.h>

#include <set>

#include "lib/units/units.h"

namespace insmc {
namespace {

TEST(Catalogue, HasThirtyThreeUniquelyNamedEntriesInVectorOrder) {
  const auto cat = catalogue();
  ASSERT_EQ(static_cast<int>(cat.size()), uncertainty_slot::kDim);
  std::set<std::string_view> names;
  for (int i = 0; i < uncertainty_slot::kDim; ++i) {
    EXPECT_EQ(cat[i].index, i);
    EXPECT_TRUE(names.insert(cat[i].name).second) << cat[i].name;
    EXPECT_GT(cat[i].default_bound_si, 0.0) << cat[i].name;
  }
}

TEST(Catalogue, DefaultBoundsFollowTable31AndTheHalfSplits) {
  const UncertaintyVector b = default_bounds();
  EXPECT_DOUBLE_EQ(b[uncertainty_slot::kAccelBias], 1e-3 * kGravityMps2);
  EXPECT_DOUBLE_EQ(b[uncertainty_slot::kGyroDrift + 2], 10 * kMeruToRadps);
  EXPECT_DOUBLE_EQ(b[uncertainty_slot::kGyroMuDrift], 5 * kMeruToRadps);
  // ζ = ζ_c + ζ_r and ∂f = ∂f_c + ∂f_r split half and half (lib/uncertainty/catalogue.cpp).
  EXPECT_DOUBLE_EQ(b[uncertainty_slot::kMisalignConst] + b[uncertainty_slot::kMisalignAlign], 1e-3);
  EXPECT_DOUBLE_EQ(b[uncertainty_slot::kBiasChangeConst] + b[uncertainty_slot::kBiasChangeAlign], 0.1 * kMgToMps2);
  EXPECT_DOUBLE_EQ(b[uncertainty_slot::kAltitudeError], 100.0);
}

TEST(Catalogue, SelectsByNameGroupAndAll) {
  EXPECT_EQ(select_uncertainties("gyro_drift"), (std::vector<int>{10, 11, 12}));
  EXPECT_EQ(select_uncertainties("gyro_drift_y"), (std::vector<int>{11}));
  EXPECT_EQ(static_cast<int>(select_uncertainties("all").size()), uncertainty_slot::kDim);
  EXPECT_TRUE(select_uncertainties("gyro").empty());  // not a group: no silent prefix match
  EXPECT_EQ(select_uncertainties("deflection"), (std::vector<int>{26, 27}));
}

TEST(Catalogue, PerAlignmentFlagsMarkOnlyTheRedrawnParts) {
  for (const auto& s : catalogue()) {
    const bool expected = s.group == "misalign_align" || s.group == "bias_change_align" ||
                          s.group == "initial_velocity";
    EXPECT_EQ(s.per_alignment, expected) << s.name;
  }
  EXPECT_EQ(find_uncertainty("theodolite_azimuth")->applies, Applies::kSystem1Only);
}

}  // namespace
}  // namespace insmc
