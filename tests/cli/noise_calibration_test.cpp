// insmc noise on a multi-position recording: the calibration section of
// noise.md, calibration.csv and noise.json's "calibration", each fitted
// value within 5 standard errors of the truth the recording was written
// with (lib/calibration/multiposition.h; a family of 30 at 5σ misses by
// chance with probability < 2e-5), a single-orientation recording left
// uncalibrated, and a bad --gravity.
#include <cmath>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <gtest/gtest.h>
#include <map>
#include <sstream>

#include "tests/cli/run_program.h"
#include "tests/unit/lib/calibration/multiposition_recording.h"
#include "tests/ordered_draws.h"

namespace insmc::testing {
namespace {

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> out;
  std::istringstream in(line);
  for (std::string c; std::getline(in, c, ',');) out.push_back(c);
  return out;
}

TEST(NoiseCalibration, AMultipositionRecordingIsCalibratedWithinItsIntervals) {
  std::mt19937_64 rng(11);
  const SensorErrors e = draw_errors(rng);
  const ImuSamples s = multiposition_recording(e, 20, 6.0, rng);
  TempDir dir;
  const std::string input = (dir.path() / "turns.csv").string(), out = (dir.path() / "out").string();
  {
    std::ofstream f(input);
    f << "t,gyro_x_dps,gyro_y_dps,gyro_z_dps,acc_x_g,acc_y_g,acc_z_g\n";
    for (std::size_t k = 0; k < s.size(); ++k)
      f << fmt::format("{:.2f},{:.12g},{:.12g},{:.12g},{:.12g},{:.12g},{:.12g}\n", s.t_s[k],
                       s.gyro_b_radps[k][0] / kDegToRad, s.gyro_b_radps[k][1] / kDegToRad,
                       s.gyro_b_radps[k][2] / kDegToRad, s.accel_b_mps2[k][0] / kGravityMps2,
                       s.accel_b_mps2[k][1] / kGravityMps2, s.accel_b_mps2[k][2] / kGravityMps2);
  }
  const ProgramResult r = run_insmc(fmt::format("noise --input {} --rate 100Hz --out {}", input, out));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("## Multi-position calibration"), std::string::npos);
  EXPECT_NE(r.out.find("21 still attitudes in 21 orientations"), std::string::npos);
  const std::map<std::string, double> truth = truth_of(e);  // the writer's g is the reader's g
  std::ifstream csv(std::filesystem::path(out) / "calibration.csv");
  std::string line;
  std::getline(csv, line);
  EXPECT_EQ(line, "recording,sensor,parameter,value,lo,hi,unit,value_si,sigma_si,lo_si,hi_si,vif,separable");
  int rows = 0;
  while (std::getline(csv, line)) {
    const auto c = split(line);
    ASSERT_EQ(c.size(), 13u) << line;
    ASSERT_TRUE(truth.count(c[2])) << c[2];
    EXPECT_LE(std::abs(std::stod(c[7]) - truth.at(c[2])), 5 * std::stod(c[8])) << line;
    EXPECT_EQ(c[12], "yes") << line;
    ++rows;
  }
  EXPECT_EQ(rows, 30);
  std::ifstream json(std::filesystem::path(out) / "noise.json");
  const std::string j((std::istreambuf_iterator<char>(json)), std::istreambuf_iterator<char>());
  EXPECT_NE(j.find("\"calibration\""), std::string::npos);
  EXPECT_NE(j.find("\"g_sensitivity_p\""), std::string::npos);
}

TEST(NoiseCalibration, OneOrientationIsNotCalibratedAndBadGravityExitsTwo) {
  TempDir dir;
  const std::string input = (dir.path() / "still.csv").string(), out = (dir.path() / "out").string();
  {
    std::ofstream f(input);
    std::mt19937_64 rng(2);
    std::normal_distribution<double> n(0, 1);
    f << "gyro_x_dps,gyro_y_dps,gyro_z_dps,acc_x_g,acc_y_g,acc_z_g\n";
    for (int k = 0; k < 6000; ++k) {
      const auto z = ordered_draws<6>(n, rng);
      f << fmt::format("{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g}\n", 0.01 * z[0], 0.01 * z[1], 0.01 * z[2],
                       1e-3 * z[3], 1e-3 * z[4], -1 + 1e-3 * z[5]);
    }
  }
  const ProgramResult r = run_insmc(fmt::format("noise --input {} --rate 10Hz --out {}", input, out));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("One static orientation"), std::string::npos);
  EXPECT_EQ(r.out.find("## Multi-position calibration"), std::string::npos);
  std::ifstream csv(std::filesystem::path(out) / "calibration.csv");
  std::string header, row;
  std::getline(csv, header);
  EXPECT_FALSE(std::getline(csv, row));  // the header only
  for (const char* g : {"1mps2", "9.5mps2", "abc", "nanmps2"}) {
    const ProgramResult b = run_insmc(fmt::format("noise --input {} --rate 10Hz --gravity {}", input, g));
    EXPECT_EQ(b.exit_code, 2) << g;
    EXPECT_NE(b.err.find("--gravity"), std::string::npos) << b.err;
  }
}

}  // namespace
}  // namespace insmc::testing
