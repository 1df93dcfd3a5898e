// Masking: a bump is found where it is, and clean recordings lose a block
// no more often than the family-wise α allows.
#include "lib/noise/disturbances.h"

#include <boost/math/distributions/binomial.hpp>
#include <gtest/gtest.h>

#include "lib/noise/noise_analysis.h"
#include "tests/unit/lib/noise/synthetic_noise.h"

namespace insmc::noise {
namespace {

SensorRecording recording(std::size_t n, double dt, std::uint64_t seed) {
  SensorRecording r;
  r.dt_s = dt;
  r.runs = {{0, n}};
  r.run_names = {"synthetic"};
  for (std::size_t c = 0; c < kChannels; ++c)
    r.channel[c] = test::synthetic_series({.white = c < 3 ? 1e-4 : 1e-3, .random_walk = c < 3 ? 1e-8 : 1e-7}, n, dt,
                                          seed * 10 + c);
  return r;
}

TEST(Disturbances, BumpIsMaskedWhereItIs) {
  SensorRecording r = recording(100 * 1200, 0.01, 3);  // 20 min at 100 Hz
  // 2 s of handling at t = 600 s: the accelerometers shake and tilt.
  for (std::size_t k = 60000; k < 60200; ++k) r.channel[3][k] += 0.05 * std::sin(static_cast<double>(k)) + 0.02;
  const DisturbanceMask m = find_disturbances(r, 0.01);
  ASSERT_EQ(m.intervals.size(), 1u);
  EXPECT_LE(m.intervals[0].start_s, 600.0);
  EXPECT_GE(m.intervals[0].end_s, 602.0);
  EXPECT_LE(m.intervals[0].end_s - m.intervals[0].start_s, 6.0);
  EXPECT_NE(m.intervals[0].channels.find("accel_x"), std::string::npos);
  EXPECT_EQ(m.kept.size(), 2u);
}

TEST(Disturbances, CleanRecordingsRarelyLoseABlock) {
  const int files = 40;
  int any = 0;
  for (int f = 0; f < files; ++f) any += !find_disturbances(recording(100 * 600, 0.01, 100 + f), 0.01).intervals.empty();
  EXPECT_LE(any, boost::math::quantile(boost::math::complement(boost::math::binomial(files, 0.01), 0.001)));
}

TEST(Stationarity, WarmUpDriftIsFoundAndCleanRunsPass) {
  // 3 h at 10 Hz, gyro x with an exponential warm-up of 1e-4 rad/s (τ 15 min).
  SensorRecording r = recording(10 * 3 * 3600, 0.1, 9);
  for (std::size_t k = 0; k < r.size(); ++k) r.channel[0][k] += 1e-4 * std::exp(-static_cast<double>(k) * 0.1 / 900);
  const NoiseAnalysis a = analyse_noise(r);
  EXPECT_TRUE(a.channels[0].stationarity.tested);
  EXPECT_FALSE(a.channels[0].stationarity.stationary);
  EXPECT_TRUE(a.channels[0].first_part_excluded);
  for (std::size_t c = 1; c < kChannels; ++c) EXPECT_TRUE(a.channels[c].stationarity.stationary) << c;
}

}  // namespace
TEST(NoiseAnalysis, RecordingsTooShortForTwoClusterTimesAreBadInputNamingWhatWasLeft) {
  // Eleven recordings of 5 samples each: no stretch is long enough for an
  // Allan deviation at two cluster times. A property of the data (exit 2),
  // never a defect (exit 3).
  SensorRecording r;
  r.dt_s = 0.01;
  for (std::size_t i = 0; i < 11; ++i) {
    r.runs.push_back({5 * i, 5 * i + 5});
    r.run_names.push_back("copy");
  }
  for (std::size_t c = 0; c < kChannels; ++c)
    r.channel[c] = test::synthetic_series({.white = 1e-4, .random_walk = 1e-8}, 55, 0.01, 7 + c);
  NoiseOptions o;
  o.mask = false;
  try {
    (void)analyse_noise(r, o);
    FAIL() << "too short recordings were analysed";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("longest undisturbed stretch holds 5 samples"), std::string::npos) << e.what();
  }
}

}  // namespace insmc::noise
