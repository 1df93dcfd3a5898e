#include "lib/alignment/alignment.h"

#include <gtest/gtest.h>

#include <cmath>

#include "lib/uncertainty/catalogue.h"
#include "lib/units/units.h"

namespace insmc {
namespace {

// The simplified steady state (2.11) drops the cross-coupling ω_ie sin L0 /
// F(0) and ω_ie cos L0 / F(0) of (2.10): relative size 1/500 with the
// default gain, so per uncertainty at its bound the difference is at most
// (1/500)·(largest misalignment term at bound) ≈ 2e-3 · 14 mrad.
constexpr double kCouplingTolRad = 1e-3 * 14e-3 * 2;

TEST(Alignment, FullSystem1AgreesWithSimplifiedWithinTheNeglectedCoupling) {
  const ModelOptions o;
  const Sensitivity3 full = full_steady_state_misalignment(System::kTheodolite, o);
  const Sensitivity3 simple = simplified_steady_state_misalignment(System::kTheodolite, o);
  const UncertaintyVector b = default_bounds();
  for (int i = 0; i < uncertainty_slot::kDim; ++i) {
    EXPECT_LT((full.col(i) - simple.col(i)).norm() * b[i], kCouplingTolRad) << catalogue()[i].name;
  }
  // and the coupling is really there: ω_ie sin L0 / F(0) feeds C_y into C_x.
  const double expected = -std::sin(o.latitude_rad) / o.leveling_gain_ratio * -1.0 / o.gravity_mps2;
  // Second-order coupling (ω_ie/F(0))² = 4e-6 is left out of `expected`.
  EXPECT_NEAR(full(0, uncertainty_slot::kAccelBias + 0), expected, 1e-5 * std::abs(expected));
}

TEST(Alignment, FullSystem2WithIntegratingLoopsEqualsEquation216) {
  const ModelOptions o;
  const Sensitivity3 full = full_steady_state_misalignment(System::kGyrocompass, o);
  const Sensitivity3 simple = simplified_steady_state_misalignment(System::kGyrocompass, o);
  EXPECT_LT((full - simple).cwiseAbs().maxCoeff(), 1e-9);
  // (2.16): C_z = −ω_doy/(ω_ie cos L0) + …: 10 meru gives 14.1 mrad.
  EXPECT_NEAR(full(2, uncertainty_slot::kGyroDrift + 1) * 10 * kMeruToRadps, -0.01 / std::cos(o.latitude_rad), 1e-12);
}

TEST(Alignment, SwitchoverAddsTheAlignmentStepZetaR) {
  const ModelOptions o;
  for (System s : {System::kTheodolite, System::kGyrocompass}) {
    const Sensitivity3 c = full_steady_state_misalignment(s, o);
    const Sensitivity3 cp = full_switchover_misalignment(s, o);
    Sensitivity3 diff = cp - c;
    for (int k = 0; k < 3; ++k) EXPECT_DOUBLE_EQ(diff(k, uncertainty_slot::kMisalignAlign + k), 1.0);
    diff.block<3, 3>(0, uncertainty_slot::kMisalignAlign).setZero();
    EXPECT_EQ(diff.cwiseAbs().maxCoeff(), 0.0);
  }
}

TEST(Alignment, PaperSwitchoverMatchesEquation218c) {
  const ModelOptions o;
  const double g = o.gravity_mps2, tanL = std::tan(o.latitude_rad);
  const Sensitivity3 c1 = paper_switchover_misalignment(System::kTheodolite, o);
  EXPECT_DOUBLE_EQ(c1(0, uncertainty_slot::kAccelBias + 1), 1 / g);
  EXPECT_DOUBLE_EQ(c1(1, uncertainty_slot::kAccelBias + 0), -1 / g);
  EXPECT_DOUBLE_EQ(c1(2, uncertainty_slot::kTheodolite), 1.0);
  EXPECT_DOUBLE_EQ(c1(0, uncertainty_slot::kGyroDrift + 0), 1 / (500 * o.earth_rate_radps));
  const Sensitivity3 c2 = paper_switchover_misalignment(System::kGyrocompass, o);
  EXPECT_DOUBLE_EQ(c2(2, uncertainty_slot::kAccelBias + 1), -tanL / g);
  EXPECT_DOUBLE_EQ(c2(2, uncertainty_slot::kMisalignAlign + 0), -tanL);  // ζ'_z(2) = ζ_z − ζ_x tan L0
  EXPECT_DOUBLE_EQ(c2(2, uncertainty_slot::kTheodolite), 0.0);
}

TEST(Alignment, TorquerCommandsOfSystem2CancelTheYDrift) {
  // (5.15b): with gyrocompassing the y command carries no ω_doy: the
  // azimuth error −ω_doy/(ω_ie cos L0) turns earth rate into exactly −ω_doy.
  const ModelOptions o;
  const Sensitivity3 c = simplified_steady_state_misalignment(System::kGyrocompass, o);
  const Sensitivity3 w = torquer_commands(c, o);
  EXPECT_NEAR(w(1, uncertainty_slot::kGyroDrift + 1), 0.0, 1e-15);
  EXPECT_DOUBLE_EQ(w(0, uncertainty_slot::kGyroDrift + 0), -1.0);
  EXPECT_DOUBLE_EQ(w(2, uncertainty_slot::kGyroDrift + 2), -1.0);
}

TEST(Alignment, LevelingNullsTheHorizontalAccelerometerOutputs) {
  // (5.18a): in steady state the x, y accelerometers read g(ψ_ω + ζ_c)
  // only: bias and deflection are levelled out.
  const ModelOptions o;
  const double g = o.gravity_mps2;
  const Sensitivity3 c = simplified_steady_state_misalignment(System::kTheodolite, o);
  const Sensitivity3 f = alignment_accelerometer_outputs(c, o);
  EXPECT_NEAR(f(0, uncertainty_slot::kAccelBias + 0), 0.0, 1e-15);
  EXPECT_NEAR(f(1, uncertainty_slot::kAccelBias + 1), 0.0, 1e-15);
  EXPECT_NEAR(f(0, uncertainty_slot::kDeflection + 0), 0.0, 1e-15);
  EXPECT_DOUBLE_EQ(f(0, uncertainty_slot::kMisalignConst + 1), g);
  EXPECT_DOUBLE_EQ(f(1, uncertainty_slot::kMisalignConst + 0), -g);
  EXPECT_DOUBLE_EQ(f(2, uncertainty_slot::kAccelScale + 2), -g);
}

}  // namespace
}  // namespace insmc
