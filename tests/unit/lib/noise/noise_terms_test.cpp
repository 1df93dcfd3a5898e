// Each term's Allan variance (IEEE Std 952 Table C.1) against its structure
// function, derived separately: σ²(τ) = (4D(τ) − D(2τ)) / (2τ²), and (N.1) at
// s = τ is 2σ²(τ).
#include "lib/noise/noise_terms.h"

#include <cmath>
#include <gtest/gtest.h>

namespace insmc::noise {
namespace {

TEST(NoiseTerms, AllanVarianceFollowsFromTheStructureFunction) {
  for (NoiseTerm t : kAllNoiseTerms)
    for (double tc : {0.5, 30.0, 2000.0})
      for (double tau : {0.01, 0.3, 1.0, 17.0, 450.0, 9000.0}) {
        const double from_d = (4 * structure_shape(t, tau, tc) - structure_shape(t, 2 * tau, tc)) / (2 * tau * tau);
        const double a = avar_shape(t, tau, tc);
        // The Gauss–Markov structure function is of order T_c·τ while its
        // second differences are of order τ³/T_c: rounding grows as (T_c/τ)².
        const double rel = t == NoiseTerm::kGaussMarkov ? 1e-7 + 1e-16 * (tc / tau) * (tc / tau) * 10 : 1e-7;
        EXPECT_NEAR(from_d, a, rel * std::abs(a) + 1e-300) << term_name(t, SensorKind::kGyro) << " tau " << tau << " tc " << tc;
        EXPECT_NEAR(mean_difference_shape(t, tau, tau, tc), 2 * a, 2 * rel * std::abs(a) + 1e-300);
      }
}

TEST(NoiseTerms, GaussMarkovLimits) {
  // τ ≫ T_c: white rate with N² = 2σ²T_c; τ ≪ T_c: random walk with K² = 2σ²/T_c.
  const double tc = 10;
  EXPECT_NEAR(avar_shape(NoiseTerm::kGaussMarkov, 1e5, tc) / (2 * tc / 1e5), 1.0, 1e-3);
  EXPECT_NEAR(avar_shape(NoiseTerm::kGaussMarkov, 1e-4, tc) / (2 / tc * 1e-4 / 3), 1.0, 1e-4);
}

TEST(NoiseTerms, RandomWalkMeanDifferenceByDirectIntegration) {
  // Brownian rate, averages over τ at starts s apart: Var = K²(s − τ/3) for s ≥ τ
  // (∫∫ overlap of [u, u+s] and [v, v+s] over the two windows, divided by τ²).
  for (double s : {2.0, 5.0, 40.0})
    EXPECT_NEAR(mean_difference_shape(NoiseTerm::kRateRandomWalk, 2.0, s, 0), s - 2.0 / 3, 1e-9);
  // Ramp: the difference of the two averages is R·s exactly.
  EXPECT_NEAR(mean_difference_shape(NoiseTerm::kRateRamp, 3.0, 10.0, 0), 100.0, 1e-9);
  // White rate, disjoint windows: 2N²/τ.
  EXPECT_NEAR(mean_difference_shape(NoiseTerm::kWhiteRate, 4.0, 9.0, 0), 0.5, 1e-12);
}

}  // namespace
}  // namespace insmc::noise
