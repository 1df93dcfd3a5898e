// insmc noise on real data, when a copy of the data is at hand
// (INSMC_REAL_DATA = the folder holding adis16405-static-calgary/ and
// allan-reference-smac/; docs/real-data/README.md says where they come
// from). Skipped otherwise: the data are not part of the repository.
//
// Known answers: the SMAC group's published overlapping Allan deviations
// of the ADIS16405 (allan_deviation_tables.csv, from the R package avar)
// are of the same 10⁶ samples as run 1; and a plain overlapping Allan
// analysis written here, a direct sum over every window.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <gtest/gtest.h>
#include <map>
#include <numbers>
#include <sstream>

#include "tests/cli/run_program.h"

namespace insmc::testing {
namespace {

std::vector<std::string> cells(const std::string& line) {
  std::vector<std::string> out;
  std::istringstream in(line);
  for (std::string c; std::getline(in, c, ',');) out.push_back(c);
  return out;
}

/// σ(τ) = √(Σ_k (ȳ_{k+m} − ȳ_k)² / (2 (N − 2m + 1))) with ȳ_k the mean of y[k, k+m): the
/// textbook form, no running sums.
double direct_adev(const std::vector<double>& y, std::size_t m) {
  std::vector<double> avg(y.size() - m + 1);
  long double window = 0;
  for (std::size_t k = 0; k < m; ++k) window += y[k];
  for (std::size_t k = 0; k + m <= y.size(); ++k) {
    avg[k] = static_cast<double>(window / static_cast<long double>(m));
    if (k + m < y.size()) window += y[k + m] - y[k];
  }
  double sum = 0;
  std::size_t n = 0;
  for (std::size_t k = 0; k + 2 * m <= y.size(); ++k, ++n) sum += (avg[k + m] - avg[k]) * (avg[k + m] - avg[k]);
  return std::sqrt(sum / (2.0 * static_cast<double>(n)));
}

TEST(NoiseRealData, AdisRun1AgainstThePublishedAndADirectAllanAnalysis) {
  const char* root = std::getenv("INSMC_REAL_DATA");
  if (!root) GTEST_SKIP() << "INSMC_REAL_DATA not set";
  const std::filesystem::path data(root);
  const auto gz = data / "adis16405-static-calgary" / "adis16405_run1_100hz.csv.gz";
  const auto table = data / "allan-reference-smac" / "allan_deviation_tables.csv";
  if (!std::filesystem::exists(gz) || !std::filesystem::exists(table)) GTEST_SKIP() << "data not found under " << root;
  TempDir dir;
  const std::string csv = (dir.path() / "run1.csv").string(), out = (dir.path() / "out").string();
  ASSERT_EQ(run_shell(fmt::format("{{ gzip -dc '{}' > '{}'; }}", gz.string(), csv)).exit_code, 0);
  const ProgramResult r =
      run_insmc(fmt::format("noise --input {} --rate 100Hz --mask off --first-part 0s --out {}", csv, out));
  ASSERT_EQ(r.exit_code, 0) << r.err;

  // Ours: channel → τ → (adev, lower, upper, model) in SI.
  std::map<std::string, std::map<long, std::array<double, 4>>> ours;
  {
    std::ifstream f(std::filesystem::path(out) / "allan.csv");
    std::string line;
    std::getline(f, line);
    while (std::getline(f, line)) {
      const auto c = cells(line);
      ours[c[0]][std::lround(std::stod(c[1]) * 100)] = {std::stod(c[2]), std::stod(c[3]), std::stod(c[4]), std::stod(c[7])};
    }
  }
  // Published: gyros in deg/s, accelerometers in g (docs/real-data/README.md).
  const std::map<std::string, std::pair<std::string, double>> names = {
      {"Gyro.X", {"gyro_x", std::numbers::pi / 180}},   {"Gyro.Y", {"gyro_y", std::numbers::pi / 180}},   {"Gyro.Z", {"gyro_z", std::numbers::pi / 180}},
      {"Accel.X", {"accel_x", 9.80665}}, {"Accel.Y", {"accel_y", 9.80665}}, {"Accel.Z", {"accel_z", 9.80665}}};
  std::ifstream f(table);
  std::string line;
  std::getline(f, line);
  int compared = 0, model_inside = 0;
  while (std::getline(f, line)) {
    const auto c = cells(line);
    if (c[0] != "adis_av.rda") continue;
    const auto& [channel, to_si] = names.at(c[5]);
    const auto it = ours[channel].find(std::lround(std::stod(c[7]) * 100));
    if (it == ours[channel].end()) continue;
    const auto [adev, lower, upper, model] = it->second;
    const double published = std::stod(c[9]) * to_si;
    // The same estimator on the same samples: measured to agree within
    // 1.7e-6 relative (the package's own arithmetic); a different estimator
    // (non-overlapping, another τ, another run) differs by percents. The exact
    // normalization is checked against the direct analysis below.
    EXPECT_NEAR(adev / published, 1.0, 1e-5) << channel << " tau " << c[7];
    ++compared;
    model_inside += model >= std::stod(c[10]) * to_si && model <= std::stod(c[11]) * to_si;
  }
  EXPECT_GE(compared, 6 * 15);
  // How closely the six standard terms follow the published curve is
  // reported, not required: the sensor's bandwidth and a ~1 s feature in the
  // accelerometers are outside the standard terms (docs/noise.md §7).
  std::printf("fitted model inside the published interval at %d of %d levels\n", model_inside, compared);

  // The direct analysis of gyro x and accel z at every other level.
  std::vector<double> gx, az;
  {
    std::ifstream in(csv);
    std::getline(in, line);
    while (std::getline(in, line)) {
      const auto c = cells(line);
      gx.push_back(std::stod(c[0]) * std::numbers::pi / 180);
      az.push_back(std::stod(c[5]) * 9.80665);
    }
  }
  for (std::size_t m = 1; 3 * m <= gx.size(); m *= 4) {
    const long key = std::lround(static_cast<double>(m));
    EXPECT_NEAR(ours["gyro_x"][key][0] / direct_adev(gx, m), 1.0, 1e-9) << m;
    EXPECT_NEAR(ours["accel_z"][key][0] / direct_adev(az, m), 1.0, 1e-9) << m;
  }
}

// The Xsens multi-position set (raw ADC counts), through the command block
// of docs/real-data/README.md: the multi-position calibration against IMU-TK's, the program the data
// were published with. Its test program, run on the same two files with
// gravity 9.81744 m/s², prints accelerometer biases 33124.2, 33275.2,
// 32364.4 counts and inverse scale factors 414.478, 412.102, 414.538
// counts/(m/s²), and gyro inverse scale factors 4776.96, 4765.68, 4769.53
// counts/(rad/s) (a published run with its lower-triangular accelerometer
// model). The conversion to columns in g and rad/s uses nominal factors
// (32768 counts mid-scale, 3724 counts/g, 6258 counts/(rad/s)); the fitted
// scale factors are relative to them.
//
// Tolerances: the two fits differ in model and in the still intervals each
// finds, not only by noise. IMU-TK's accelerometer misalignment is lower
// triangular where insmc's is upper: the scale factors then differ at second
// order in the misalignments (0.02² = 4e-4, hence 0.05 %), the biases within
// the ADC's step (1 count). IMU-TK takes the gyro bias from the first 50 s
// and fits no g-sensitivity; insmc fits both over all attitudes: the biases
// differ by up to 9 counts (1.4e-3 rad/s), which over turns at ~1 rad/s
// moves a gyro scale factor by ~0.15 % (hence 0.2 %).
TEST(NoiseRealData, XsensMultipositionAgainstImuTk) {
  const char* root = std::getenv("INSMC_REAL_DATA");
  if (!root) GTEST_SKIP() << "INSMC_REAL_DATA not set";
  const std::filesystem::path data = std::filesystem::path(root) / "xsens-mti-multiposition-imutk";
  if (!std::filesystem::exists(data / "xsens_acc.mat")) GTEST_SKIP() << "data not found under " << root;
  // The command block of docs/real-data/README.md's Xsens section, as
  // pasted: its data folder, program and working folder replaced.
  const char* src = std::getenv("INSMC_SOURCE_DIR");
  ASSERT_NE(src, nullptr);
  const std::string doc = read_file(std::filesystem::path(src) / "docs" / "real-data" / "README.md");
  const std::size_t at = doc.find("\nXSENS=");
  ASSERT_NE(at, std::string::npos) << "no ```sh block with XSENS= in docs/real-data/README.md";
  const std::size_t open = doc.rfind("```sh\n", at), close = doc.find("\n```", at);
  std::istringstream lines(doc.substr(open + 6, close - open - 6));
  TempDir dir;
  std::string script = "set -e -o pipefail\n", line;
  while (std::getline(lines, line)) {
    if (line.rfind("XSENS=", 0) == 0) line = "XSENS='" + data.string() + "'";
    if (line.rfind("INSMC=", 0) == 0) line = "INSMC='" + insmc_path() + "'";
    for (std::size_t p = line.find("/tmp/xsens"); p != std::string::npos; p = line.find("/tmp/xsens"))
      line.replace(p, 10, dir.path().string());
    script += line + "\n";
  }
  std::ofstream(dir.path() / "block.sh") << script;
  const ProgramResult r = run_shell(fmt::format("cd '{}' && bash '{}'", src, (dir.path() / "block.sh").string()));
  ASSERT_EQ(r.exit_code, 0) << script << "\n" << r.err;
  const std::filesystem::path out = dir.path() / "noise_xsens";
  std::map<std::string, double> value;
  {
    std::ifstream f(out / "calibration.csv");
    std::getline(f, line);
    while (std::getline(f, line)) {
      const auto c = cells(line);
      value[c[2]] = std::stod(c[7]);
      EXPECT_EQ(c[12], "yes") << line;
    }
  }
  ASSERT_EQ(value.size(), 30u);
  const double accel_bias[] = {33124.2, 33275.2, 32364.4}, accel_inverse[] = {414.478, 412.102, 414.538},
               gyro_inverse[] = {4776.96, 4765.68, 4769.53};
  for (int i = 0; i < 3; ++i) {
    const std::string a(1, "xyz"[i]);
    EXPECT_NEAR(32768 + value["accel_bias_" + a] / 9.80665 * 3724, accel_bias[i], 1.0) << a;
    EXPECT_NEAR(3724 / (9.80665 * (1 + value["accel_scale_factor_" + a])) / accel_inverse[i], 1.0, 5e-4) << a;
    EXPECT_NEAR(6258 / (1 + value["gyro_scale_factor_" + a]) / gyro_inverse[i], 1.0, 2e-3) << a;
  }
}

}  // namespace
}  // namespace insmc::testing
