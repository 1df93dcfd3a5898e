// Records of a noisy sensor through `import-imu`: a stationary IMU whose
// outputs carry white rate noise and a Gauss–Markov bias on every axis
// (tests/unit/lib/noise/synthetic_noise.h, written apart from the
// diagnosis's own synthesizer), tactical grade, several times Table 3.1. The
// raw-sensor stage fits that noise, and the diagnosis's null goes through
// the import with it (montecarlo/records/gap/null/import_null.h): such a sensor
// matches its own noise, so it is not an unmodelled effect (false alarms
// consistent with alpha), while against the model alone (Table 3.1, a
// perfect sensor) its gap is significant: the null through the import is
// what tells the two apart.
//
// CI runs one file: its power is in the second check (a sensor this far
// outside Table 3.1 is significant against the model alone; it fails if the
// import's null or the raw stage break). The false-alarm rate needs many
// files (its binomial bound is vacuous below ten), the long measurement
// (docs/gap-method.md §2):
//   INSMC_GAP_IMPORTED_NOISE_FILES=50 build/test/tests/cli/cli_gap_imported_noise_test
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <iterator>
#include <utility>
#include <string>

#include "tests/cli/gap_null_files.h"
#include "tests/cli/run_program.h"
#include "tests/unit/lib/imu/synthetic_imu.h"
#include "tests/unit/lib/noise/synthetic_noise.h"

namespace insmc::testing {
namespace {

/// The number after `"key": ` in a JSON text (NaN when absent).
double number_after(const std::string& json, const std::string& key) {
  const auto at = json.find("\"" + key + "\": ");
  return at == std::string::npos ? std::nan("") : std::strtod(json.c_str() + at + key.size() + 4, nullptr);
}

constexpr double kRateHz = 10;
constexpr double kDurationS = 300.0 + 900.0 + 5400.0 + 1.0;  // alignment, test run, navigation
constexpr int kRuns = 8;

/// Gyros: ARW 0.3 deg/√h and a Gauss–Markov 3 deg/h over 600 s;
/// accelerometers: VRW 0.06 m/s/√h and a Gauss–Markov 100 µg over 600 s.
noise::test::SyntheticNoise gyro_noise() {
  noise::test::SyntheticNoise n;
  n.white = 0.3 / 60 * kDegToRad;
  n.gm_sigma = 3.0 / 3600 * kDegToRad;
  n.gm_time_s = 600;
  return n;
}
noise::test::SyntheticNoise accel_noise() {
  noise::test::SyntheticNoise n;
  n.white = 0.06 / 60;
  n.gm_sigma = 100e-6 * kGravityMps2;
  n.gm_time_s = 600;
  return n;
}

/// A navigation-grade unit, well inside Table 3.1 over a Schuler period:
/// gyros ARW 0.001 deg/√h and 0.005 deg/h over 600 s; accelerometers VRW
/// 0.001 m/s/√h and 5 µg over 600 s.
noise::test::SyntheticNoise navigation_gyro_noise() {
  noise::test::SyntheticNoise n;
  n.white = 0.001 / 60 * kDegToRad;
  n.gm_sigma = 0.005 / 3600 * kDegToRad;
  n.gm_time_s = 600;
  return n;
}
noise::test::SyntheticNoise navigation_accel_noise() {
  noise::test::SyntheticNoise n;
  n.white = 0.001 / 60;
  n.gm_sigma = 5e-6 * kGravityMps2;
  n.gm_time_s = 600;
  return n;
}

/// One run's CSV (deg/s and g, 10 significant digits: far below the noise).
void write_run(const std::filesystem::path& path, const SyntheticSite& site, std::uint64_t seed,
               const noise::test::SyntheticNoise& gyro = gyro_noise(),
               const noise::test::SyntheticNoise& accel = accel_noise()) {
  const auto n = static_cast<std::size_t>(std::lround(kDurationS * kRateHz));
  std::array<std::vector<double>, 6> noise;
  for (std::size_t c = 0; c < 6; ++c)
    noise[c] = noise::test::synthetic_series(c < 3 ? gyro : accel, n, 1 / kRateHz, seed * 8 + c);
  const ImuSamples s = synthetic_samples(site, kRateHz, kDurationS);
  std::ofstream f(path);
  f << "gyro_x_dps,gyro_y_dps,gyro_z_dps,acc_x_g,acc_y_g,acc_z_g\n";
  for (std::size_t k = 0; k < s.size(); ++k) {
    const Vec3& g = s.gyro_b_radps[k];
    const Vec3& a = s.accel_b_mps2[k];
    f << fmt::format("{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g}\n", (g.x() + noise[0][k]) / kDegToRad,
                     (g.y() + noise[1][k]) / kDegToRad, (g.z() + noise[2][k]) / kDegToRad,
                     (a.x() + noise[3][k]) / kGravityMps2, (a.y() + noise[4][k]) / kGravityMps2,
                     (a.z() + noise[5][k]) / kGravityMps2);
  }
}

std::string read_file(const std::string& path) {
  std::ifstream f(path);
  return {std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>()};
}

/// Records through the import carry two verdicts, stated once each and in
/// one order: against the model, then against the unit's own noise; each
/// as significant as its p says; the figures name their null and draw the
/// band of the one they are judged against.
void expect_verdicts_in_order(const std::string& json, const std::string& out) {
  const std::string md = read_file(out + "/gap.md");
  const auto first = md.find("1. **Against the model**");
  const auto second = md.find("2. **Against the unit's own noise**");
  ASSERT_NE(first, std::string::npos) << md.substr(0, 3000);
  ASSERT_NE(second, std::string::npos) << md.substr(0, 3000);
  EXPECT_LT(first, second);
  const auto headline_model = md.find("Against the model: ");
  const auto headline_own = md.find("against the unit's own noise through the import: ");
  EXPECT_LT(headline_model, first);
  EXPECT_LT(headline_model, headline_own);
  // The JSON's verdicts in the same order, and each verdict's words as its p.
  const auto model_at = json.find("\"against\": \"the model\"");
  const auto own_at = json.find("\"against\": \"the unit's own noise\"");
  ASSERT_NE(model_at, std::string::npos);
  ASSERT_NE(own_at, std::string::npos);
  EXPECT_LT(model_at, own_at);
  const std::string alpha_text = "alpha = 0.01";  // the default level
  for (const auto& [at, end] : {std::pair{first, second}, std::pair{second, md.find("\n\n", second)}}) {
    const std::string line = md.substr(at, end - at);
    const auto p_at = line.find("G+ = ");
    ASSERT_NE(p_at, std::string::npos) << line;
    const double p_value = std::strtod(line.c_str() + line.find(", p = ", p_at) + 6, nullptr);
    ASSERT_NE(line.find(alpha_text), std::string::npos) << line;
    EXPECT_EQ(line.find("**significant gap**") != std::string::npos, p_value < 0.01) << line;
  }
  // Section 2 says which null its table shows; the groups figure draws both bands, the Allan figure a panel each.
  EXPECT_NE(md.find("Against the model (verdict 1): each group's"), std::string::npos);
  EXPECT_NE(md.find("own-noise band"), std::string::npos);
  const std::string groups = read_file(out + "/gap_groups.gp");
  EXPECT_NE(groups.find("the model's null files: band"), std::string::npos);
  EXPECT_NE(groups.find("the sensor's own noise through the import: band"), std::string::npos);
  const std::string allan = read_file(out + "/gap_allan.gp");
  EXPECT_NE(allan.find("against the model (verdict 1)"), std::string::npos);
  EXPECT_NE(allan.find("against the unit's own noise (verdict 2)"), std::string::npos);
}

TEST(GapImportedNoise, ASensorThatMatchesItsOwnNoiseIsNotAnUnmodelledEffect) {
  const int files = null_files_from_env("INSMC_GAP_IMPORTED_NOISE_FILES", 1);
  // INSMC_GAP_IMPORTED_NOISE_FIRST=K: start at file K - 1 (a long study in parts).
  const int first = null_files_from_env("INSMC_GAP_IMPORTED_NOISE_FIRST", 1) - 1;
  const double alpha = 0.01;
  int unmodelled = 0, against_model = 0;
  for (int file = first; file < first + files; ++file) {
    TempDir dir;
    SyntheticSite site;
    site.latitude_rad = std::array{45.0, -33.9, 60.0}[static_cast<std::size_t>(file % 3)] * kDegToRad;
    site.heading_rad = 23.0 * file * kDegToRad;
    site.pitch_rad = 0.3 * (file % 2) * kDegToRad;
    std::string inputs;
    for (int run = 0; run < kRuns; ++run) {
      const auto path = dir.path() / fmt::format("run{}.csv", run);
      write_run(path, site, 1000 * static_cast<std::uint64_t>(file) + static_cast<std::uint64_t>(run));
      inputs += " --input " + path.string();
    }
    const std::string records = (dir.path() / "records.csv").string();
    const auto imported = run_insmc(fmt::format("import-imu{} --rate {}Hz --latitude {:.6f}deg --azimuth {:.6f}deg --out {}",
                                                inputs, kRateHz, site.latitude_rad / kDegToRad,
                                                site.heading_rad / kDegToRad, records));
    ASSERT_EQ(imported.exit_code, 0) << imported.err;
    const std::string out = (dir.path() / "gap").string();
    const auto r = run_insmc(
        fmt::format("gap --records {} --format json --seed {} --rank never --out {}", records, 1 + file, out));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    expect_verdicts_in_order(r.out, out);
    ASSERT_TRUE(r.out.find("\"null\": \"the model and the sensor's noise through the import\"") != std::string::npos)
        << r.out.substr(0, 4000);
    const bool u = significant_after(r.out, "gap"), m = significant_after(r.out, "against_model");
    unmodelled += u;
    against_model += m;
    fmt::print("file {:3d}: beyond its own noise {} (p = {:.4g}), against the model alone {} (p = {:.4g})\n", file, u,
               number_after(object_after(r.out, "gap"), "p_value"), m,
               number_after(object_after(r.out, "against_model"), "p_value"));
  }
  const int bound = binomial_bound(files, alpha);
  fmt::print("{} files of a tactical-grade sensor through import-imu: {} significant beyond its own noise, {} against "
             "the model alone; at most {} false alarms expected (P(more) < 1e-3 at alpha = {})\n",
             files, unmodelled, against_model, bound, alpha);
  EXPECT_LE(unmodelled, bound);
  // The sensor is far outside Table 3.1: against the model alone every file is a gap.
  EXPECT_EQ(against_model, files);
}

// A navigation-grade unit well inside Table 3.1, through the import: the
// first sentence says its noise is within the bounds and never names an
// unmodelled effect the second verdict does not find; it agrees with both
// verdicts printed beside it.
TEST(GapImportedNoise, AUnitWithinThePriorsIsSaidToBeAndItsHeadlineAgreesWithBothVerdicts) {
  TempDir dir;
  SyntheticSite site;
  site.latitude_rad = 45.0 * kDegToRad;
  site.heading_rad = 30.0 * kDegToRad;
  std::string inputs;
  for (int run = 0; run < kRuns; ++run) {
    const auto path = dir.path() / fmt::format("run{}.csv", run);
    write_run(path, site, 7000 + static_cast<std::uint64_t>(run), navigation_gyro_noise(), navigation_accel_noise());
    inputs += " --input " + path.string();
  }
  const std::string records = (dir.path() / "records.csv").string();
  const auto imported = run_insmc(fmt::format("import-imu{} --rate {}Hz --latitude 45deg --azimuth 30deg --out {}",
                                              inputs, kRateHz, records));
  ASSERT_EQ(imported.exit_code, 0) << imported.err;
  const std::string out = (dir.path() / "gap").string();
  const auto r = run_insmc(fmt::format("gap --records {} --format json --seed 3 --rank never --out {}", records, out));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  expect_verdicts_in_order(r.out, out);
  const std::string finding = r.out.substr(r.out.find("\"finding\": "), 1200);
  fmt::print("{}\n", finding.substr(0, finding.find("\",\n")));
  const bool model = significant_after(r.out, "against_model"), own = significant_after(r.out, "gap");
  EXPECT_NE(finding.find("Table 3.1's bounds (raw-sensor stage: within them)"), std::string::npos) << finding;
  EXPECT_EQ(finding.find("An unmodelled effect"), std::string::npos) << finding;
  if (!own) {
    EXPECT_NE(finding.find(model ? "The gap against the model is the unit's own sensor noise"
                                 : "The data agree with the model and with the unit's own noise"),
              std::string::npos)
        << finding;
  }
}

}  // namespace
}  // namespace insmc::testing
