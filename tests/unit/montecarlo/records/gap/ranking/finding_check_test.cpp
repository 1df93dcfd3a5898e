// The first-ranked finding corrected by its fit on files simulated with it
// (montecarlo/records/gap/ranking/finding_check.h).
#include <gtest/gtest.h>

#include <cmath>

#include "montecarlo/records/gap/ranking/finding_check.h"

namespace insmc::gap {
namespace {

ParameterEstimate estimate(double value, double low, double high) {
  return {"sigma", Dimension::kAcceleration, value, low, high, false, {}};
}

TEST(FindingCheck, ALogarithmicBiasScalesTheValueAndTheRange) {
  // Fits 10 % high on average: the value comes down by the ratio; with no
  // spread the range keeps its ratios to the value.
  SimulatedCheck c{true, 6, 2.0, true, std::log(1.1), 0.0};
  const ParameterEstimate e = corrected(estimate(2.2, 2.0, 2.5), c);
  EXPECT_NEAR(e.value, 2.0, 1e-12);
  EXPECT_NEAR(e.low, 2.0 * 2.0 / 2.2, 1e-12);
  EXPECT_NEAR(e.high, 2.5 * 2.0 / 2.2, 1e-12);
  EXPECT_TRUE(e.check.measured);
}

TEST(FindingCheck, TheBiasUncertaintyWidensEachSideInQuadrature) {
  // Spread 0.3 over 9 files: a standard error of 0.1 in ln, added to each
  // side's 0.1 in quadrature.
  SimulatedCheck c{true, 9, 1.0, true, 0.0, 0.3};
  const ParameterEstimate e = corrected(estimate(1.0, std::exp(-0.1), std::exp(0.1)), c);
  EXPECT_NEAR(std::log(e.low), -std::hypot(0.1, 0.1), 1e-12);
  EXPECT_NEAR(std::log(e.high), std::hypot(0.1, 0.1), 1e-12);
}

TEST(FindingCheck, ALinearBiasShiftsASignedAmplitude) {
  SimulatedCheck c{true, 4, -1.0, false, 0.2, 0.0};
  const ParameterEstimate e = corrected(estimate(-0.8, -1.1, -0.6), c);
  EXPECT_NEAR(e.value, -1.0, 1e-12);
  EXPECT_NEAR(e.low, -1.3, 1e-12);
  EXPECT_NEAR(e.high, -0.8, 1e-12);
}

TEST(FindingCheck, ARatioDoesNotApplyToARangeReachingZero) {
  SimulatedCheck c{true, 6, 1.0, true, 0.5, 0.1};
  const ParameterEstimate e = corrected(estimate(1.0, 0.0, 2.0), c);
  EXPECT_EQ(e.value, 1.0);
  EXPECT_EQ(e.low, 0.0);
}

}  // namespace
}  // namespace insmc::gap
