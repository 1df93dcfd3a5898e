// The IEEE slope readings on Allan curves of known terms (the formulas of
// lib/noise/noise_terms.h, no estimation noise): each term read where it
// dominates, the +½ reading only where the curve ends on that slope.
#include "lib/noise/slope_readings.h"

#include <cmath>
#include <gtest/gtest.h>
#include <numbers>
#include <vector>

#include "lib/noise/noise_fit.h"

namespace insmc::noise {
namespace {

std::vector<AllanRow> curve(const NoiseModel& m, int levels) {
  std::vector<AllanRow> rows;
  for (int j = 0; j < levels; ++j) {
    AllanRow r;
    r.tau_s = 0.01 * std::ldexp(1.0, j);
    r.adev = std::sqrt(m.avar(r.tau_s));
    r.lower = 0.95 * r.adev, r.upper = 1.05 * r.adev;
    rows.push_back(r);
  }
  return rows;
}

TEST(SlopeReadings, EachTermIsReadWhereItDominates) {
  // N = 1e-3 and K = 1e-7 (SI): white noise up to their crossing at
  // √3 N/K ≈ 1.7e4 s, the walk beyond (to 3.4e5 s); the −½ line read at
  // 1 s, the +½ line at 3 s.
  NoiseModel m;
  m[NoiseTerm::kWhiteRate] = 1e-6;
  m[NoiseTerm::kRateRandomWalk] = 1e-14;
  const SlopeReadings r = read_slopes(curve(m, 26));
  ASSERT_TRUE(r.white.found);
  EXPECT_NEAR(r.white.value_si, 1e-3, 0.02e-3);
  ASSERT_TRUE(r.walk.found);
  EXPECT_NEAR(r.walk.value_si, 1e-7, 0.1e-7);
  // The floor of white + walk: min σ = √(2NK/√3) at τ = √3 N/K; /0.664.
  const double floor = std::sqrt(2 * 1e-3 * 1e-7 / std::sqrt(3.0));
  EXPECT_NEAR(r.instability.value_si * std::sqrt(2 * std::log(2.0) / std::numbers::pi), floor, 0.03 * floor);
}

TEST(SlopeReadings, AFlatFloorIsTheBiasInstabilityAndNoWalkIsReadWithoutARise) {
  NoiseModel m;
  m[NoiseTerm::kWhiteRate] = 1e-6;
  m[NoiseTerm::kBiasInstability] = 1e-10;  // B = 1e-5
  const std::vector<AllanRow> rows = curve(m, 24);
  const SlopeReadings r = read_slopes(rows);
  EXPECT_FALSE(r.walk.found);
  ASSERT_TRUE(r.instability.found);
  // The floor is the last level, where σ² = (2 ln 2/π) B² + N²/τ: the
  // reading is that over 0.664, exactly.
  const double last = rows.back().tau_s, k = 2 * std::numbers::ln2 / std::numbers::pi;
  EXPECT_NEAR(r.instability.value_si, std::sqrt(k * 1e-10 + 1e-6 / last) / std::sqrt(k), 1e-12);
  // Each level's σ√τ on the −½ stretch lies between N and its value at the
  // stretch's end (σ√τ grows with τ), so does their geometric mean.
  ASSERT_TRUE(r.white.found);
  EXPECT_GE(r.white.value_si, 1e-3);
  EXPECT_LE(r.white.value_si, std::sqrt(m.avar(r.white.tau_to_s) * r.white.tau_to_s));
  EXPECT_LE(r.white.tau_from_s, 1.0);
}

TEST(SlopeReadings, AStuckChannelHasNothingToRead) {
  std::vector<AllanRow> rows(10);
  for (int j = 0; j < 10; ++j) rows[static_cast<std::size_t>(j)].tau_s = 0.01 * std::ldexp(1.0, j);
  const SlopeReadings r = read_slopes(rows);
  EXPECT_FALSE(r.white.found || r.instability.found || r.walk.found);
}

}  // namespace
}  // namespace insmc::noise
