// Synthetic raw IMUs through import-imu and gap: with the raw-sensor stage
// in the header, gyro-only noise ranks a gyro effect first and
// accelerometer-only noise an accelerometer effect (docs/gap-method.md §4). Each
// file: six recordings of 6,700 s at 1 Hz, a level sensor (x north, z down)
// at 45°, earth rate and gravity exact. INSMC_RAW_RANKING_FILES files per
// case (default 1; the measured study used more).
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <gtest/gtest.h>
#include <numbers>
#include <random>

#include "montecarlo/records/gap/candidates/raw_limits.h"
#include "tests/cli/run_program.h"

namespace insmc::testing {
namespace {

enum class Noisy { kGyros, kAccelerometers };

/// Writes the six recordings and returns the --input list.
std::string write_recordings(const TempDir& dir, Noisy noisy, std::uint64_t seed) {
  constexpr double kDeg = std::numbers::pi / 180, kEarth = 7.292115e-5, kG = 9.80665;
  const double lat = 45 * kDeg;
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> e(0.0, 1.0);
  std::string inputs;
  for (int run = 0; run < 6; ++run) {
    const auto path = dir.path() / fmt::format("run{}.csv", run);
    std::ofstream f(path);
    f << "gyro_x_dps,gyro_y_dps,gyro_z_dps,acc_x_g,acc_y_g,acc_z_g\n";
    // Gyros: ARW 2.4 deg/√h and a Gauss–Markov 25 deg/h, 600 s; accelerometers:
    // VRW 0.05 m/s/√h and a Gauss–Markov 50 µg, 600 s.
    const bool gyro = noisy == Noisy::kGyros;
    const double white = gyro ? 2.4 / 60 * kDeg : 0.05 / 60 / kG;  // per √s, column units (rad or g)
    const double sigma = gyro ? 25.0 / 3600 * kDeg : 50e-6, phi = std::exp(-1.0 / 600);
    double gm[3] = {sigma * e(rng), sigma * e(rng), sigma * e(rng)};
    for (int k = 0; k < 6700; ++k) {
      double noise[3];
      for (int a = 0; a < 3; ++a) {
        noise[a] = white * e(rng) + gm[a];
        gm[a] = phi * gm[a] + sigma * std::sqrt(1 - phi * phi) * e(rng);
      }
      const double wx = kEarth * std::cos(lat), wz = -kEarth * std::sin(lat);
      if (gyro)
        f << fmt::format("{:.12g},{:.12g},{:.12g},0,0,-1\n", (wx + noise[0]) / kDeg, noise[1] / kDeg, (wz + noise[2]) / kDeg);
      else
        f << fmt::format("{:.12g},0,{:.12g},{:.9g},{:.9g},{:.9g}\n", wx / kDeg, wz / kDeg, noise[0], noise[1], -1 + noise[2]);
    }
    inputs += " --input " + path.string();
  }
  return inputs;
}

std::string top_effect(const std::string& gap_json) {
  const std::size_t key = gap_json.find("\"top\": \"");
  if (key == std::string::npos) return "";
  const std::size_t start = key + 8;
  return gap_json.substr(start, gap_json.find('"', start) - start);
}

int files_per_case() {
  const char* n = std::getenv("INSMC_RAW_RANKING_FILES");
  return n ? std::max(1, std::atoi(n)) : 1;
}

void run_case(Noisy noisy, const std::string& expected_sensor) {
  const int files = files_per_case();
  int right = 0;
  for (int f = 0; f < files; ++f) {
    TempDir dir;
    const std::string inputs = write_recordings(dir, noisy, 100 + static_cast<std::uint64_t>(f));
    const std::string records = (dir.path() / "records.csv").string();
    const ProgramResult imp = run_insmc(fmt::format("import-imu{} --rate 1Hz --latitude 45deg --out {}", inputs, records));
    ASSERT_EQ(imp.exit_code, 0) << imp.err;
    const ProgramResult gap = run_insmc(fmt::format("gap --records {} --format json --seed {}", records, f + 1));
    ASSERT_EQ(gap.exit_code, 0) << gap.err;
    const std::string top = top_effect(gap.out);
    right += insmc::gap::sensor_of_effect(top) == expected_sensor;
    if (files == 1) {
      EXPECT_EQ(insmc::gap::sensor_of_effect(top), expected_sensor) << top;
    }
  }
  std::printf("%s-only noise: the top effect is of that sensor in %d of %d files\n", expected_sensor.c_str(), right, files);
  // At least nine in ten (the acceptance's rate), whole files.
  EXPECT_GE(10 * right, 9 * files);
}

TEST(RawRanking, GyroOnlyNoiseRanksAGyroEffectFirst) { run_case(Noisy::kGyros, "gyro"); }
TEST(RawRanking, AccelerometerOnlyNoiseRanksAnAccelerometerEffectFirst) {
  run_case(Noisy::kAccelerometers, "accelerometer");
}

}  // namespace
}  // namespace insmc::testing
