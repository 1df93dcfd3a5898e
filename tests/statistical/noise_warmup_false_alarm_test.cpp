// The warm-up test (lib/noise/stationarity.h) on stationary synthetic
// recordings through the whole noise stage, fixed seeds: Σ z² ~ χ²(runs)
// under the rest's model, so each channel's first hour is flagged with
// probability α; the count over the channels is at most the binomial upper
// quantile at 0.001. (The test it replaces, the two ends of the first
// part, flagged 14 of 54 stationary channels at α = 0.01.)
#include <gtest/gtest.h>

#include <boost/math/distributions/binomial.hpp>
#include <numbers>

#include "lib/noise/noise_analysis.h"
#include "tests/unit/lib/noise/synthetic_noise.h"

namespace insmc::noise {
namespace {

constexpr double kDegph = std::numbers::pi / 180 / 3600;  // deg/h in rad/s

TEST(NoiseWarmUp, StationaryRecordingsLoseTheirFirstHourAtTheTestsLevel) {
  // 2 h at 10 Hz per file (the first hour against the second), six channels:
  // gyros with white noise, a Gauss–Markov bias and a rate random walk of a
  // tactical (ARW 0.15 deg/√h, 3 deg/h with T_c 20 s, 8 deg/h/√h) or a
  // navigation grade (0.003 deg/√h, 0.01 deg/h with T_c 300 s,
  // 0.1 deg/h/√h); accelerometers white + Gauss–Markov.
  const test::SyntheticNoise tactical{
      .white = 9 * kDegph, .random_walk = 8.0 / 60 * kDegph, .gm_sigma = 3 * kDegph, .gm_time_s = 20};
  const test::SyntheticNoise navigation{
      .white = 0.18 * kDegph, .random_walk = 0.1 / 60 * kDegph, .gm_sigma = 0.01 * kDegph, .gm_time_s = 300};
  const test::SyntheticNoise accelerometer{.white = 1e-3, .gm_sigma = 2e-4, .gm_time_s = 100};
  constexpr int kFiles = 3;
  constexpr double kDt = 0.1;
  NoiseOptions o;
  o.alpha = 0.05;
  int tested = 0, flagged = 0;
  for (int f = 0; f < kFiles; ++f) {
    SensorRecording r;
    r.dt_s = kDt;
    const std::size_t n = 2 * 36000;
    r.runs = {{0, n}};
    r.run_names = {"stationary"};
    for (std::size_t c = 0; c < kChannels; ++c)
      r.channel[c] = test::synthetic_series(c < 3 ? (c % 2 ? navigation : tactical) : accelerometer, n, kDt,
                                            5000 + 10 * static_cast<std::uint64_t>(f) + c);
    const NoiseAnalysis a = analyse_noise(r, o);
    for (const ChannelNoise& ch : a.channels) {
      tested += ch.stationarity.tested;
      flagged += ch.stationarity.tested && !ch.stationarity.stationary;
    }
  }
  EXPECT_EQ(tested, kFiles * 6);
  EXPECT_LE(flagged, boost::math::quantile(boost::math::complement(boost::math::binomial(tested, o.alpha), 0.001)))
      << flagged << " of " << tested;
}

}  // namespace
}  // namespace insmc::noise
