// Records of a noisy sensor through `import-imu`: a stationary IMU whose
// outputs carry white rate noise and a Gauss–Markov bias on every axis
// (tests/unit/lib/noise/synthetic_noise.h, written apart from the
// diagnosis's own synthesizer), tactical grade, several times Table 3.1. The
// raw-sensor stage fits that noise, and the diagnosis's null goes through
// the import with it (montecarlo/gap/null/import_null.h): such a sensor
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

/// One run's CSV (deg/s and g, 10 significant digits: far below the noise).
void write_run(const std::filesystem::path& path, const SyntheticSite& site, std::uint64_t seed) {
  const auto n = static_cast<std::size_t>(std::lround(kDurationS * kRateHz));
  std::array<std::vector<double>, 6> noise;
  for (std::size_t c = 0; c < 6; ++c)
    noise[c] = noise::test::synthetic_series(c < 3 ? gyro_noise() : accel_noise(), n, 1 / kRateHz, seed * 8 + c);
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
    const auto r = run_insmc(fmt::format("gap --records {} --format json --seed {} --rank never", records, 1 + file));
    ASSERT_EQ(r.exit_code, 0) << r.err;
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

}  // namespace
}  // namespace insmc::testing
