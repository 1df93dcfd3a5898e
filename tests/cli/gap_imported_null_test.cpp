// Records of a perfect sensor through `import-imu`: a stationary strapdown
// IMU without any error (tests/unit/lib/imu/synthetic_imu.h: the exact
// outputs of a sensor fixed to the model earth), logged as real loggers do
// (a rate of 5-20 Hz, numbers to 7, 9 or 17 significant digits, tilted and
// turned on its mount), imported with the importer's own conventions
// (leveling and gyro-bias estimate over its alignment window, continuous f).
// Such records scatter far less than Table 3.1 lets a system scatter, and
// their runs are alike to the last digit: the diagnosis may call the model
// pessimistic about them, never an unmodelled effect (docs/gap-method.md §2).
//
// CI runs a few files; the long measurement (docs/gap-method.md §2):
//   INSMC_GAP_IMPORTED_FILES=50 build/gap/tests/cli/cli_gap_imported_null_test
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdlib>
#include <fmt/format.h>
#include <fstream>
#include <string>

#include "tests/cli/gap_null_files.h"
#include "tests/cli/run_program.h"
#include "tests/unit/lib/imu/synthetic_imu.h"

namespace insmc::testing {
namespace {

struct ImportShape {
  SyntheticSite site;
  double rate_hz = 10;
  int digits = 17;  ///< significant digits the logger writes (17: exact)
  int runs = 8;
  double interval_s = 10;
};

/// The file's shape from its index: every combination comes round.
ImportShape shape_of(int file) {
  ImportShape s;
  s.site.latitude_rad = std::array{45.0, 51.08, -33.9, 10.0, 70.0}[static_cast<std::size_t>(file % 5)] * kDegToRad;
  s.site.heading_rad = (37.0 * file) * kDegToRad;
  s.site.pitch_rad = std::array{0.0, 0.4, -1.2}[static_cast<std::size_t>(file % 3)] * kDegToRad;
  s.site.roll_rad = std::array{0.0, -0.7}[static_cast<std::size_t>(file % 2)] * kDegToRad;
  s.rate_hz = std::array{10.0, 5.0, 20.0}[static_cast<std::size_t>((file / 2) % 3)];
  s.digits = std::array{17, 9, 7}[static_cast<std::size_t>((file / 3) % 3)];
  s.runs = (file / 5) % 2 ? 20 : 8;
  s.interval_s = std::array{10.0, 5.0, 20.0}[static_cast<std::size_t>((file / 4) % 3)];
  return s;
}

/// One run's CSV: 300 s of alignment, 15 min of test run, 90 min of navigation.
std::string perfect_csv(const ImportShape& shape) {
  const ImuSamples s = synthetic_samples(shape.site, shape.rate_hz, 300.0 + 900.0 + 5400.0 + 1.0);
  std::string out = "gyro_x_dps,gyro_y_dps,gyro_z_dps,acc_x_g,acc_y_g,acc_z_g\n";
  out.reserve(s.size() * 6 * (shape.digits + 8));
  for (std::size_t k = 0; k < s.size(); ++k) {
    const Vec3 g = s.gyro_b_radps[k] / kDegToRad, a = s.accel_b_mps2[k] / kGravityMps2;
    out += fmt::format("{:.{}g},{:.{}g},{:.{}g},{:.{}g},{:.{}g},{:.{}g}\n", g.x(), shape.digits, g.y(), shape.digits,
                       g.z(), shape.digits, a.x(), shape.digits, a.y(), shape.digits, a.z(), shape.digits);
  }
  return out;
}

TEST(GapImportedNull, APerfectSensorThroughImportImuIsNeverAnUnmodelledEffect) {
  const int files = null_files_from_env("INSMC_GAP_IMPORTED_FILES", 2);
  const double alpha = 0.01;
  TempDir dir;
  int unmodelled = 0, pessimistic = 0;
  for (int file = 0; file < files; ++file) {
    const ImportShape s = shape_of(file);
    const std::string csv = (dir.path() / fmt::format("imu_{}.csv", file)).string();
    const std::string records = (dir.path() / fmt::format("imported_{}.csv", file)).string();
    std::ofstream(csv) << perfect_csv(s);
    std::string inputs;
    for (int run = 0; run < s.runs; ++run) inputs += " --input " + csv;
    const auto imported = run_insmc(fmt::format(
        "import-imu{} --rate {}Hz --latitude {:.6f}deg --azimuth {:.6f}deg --interval {}s --out {}", inputs, s.rate_hz,
        s.site.latitude_rad / kDegToRad, s.site.heading_rad / kDegToRad, s.interval_s, records));
    ASSERT_EQ(imported.exit_code, 0) << imported.err;
    // The first file goes through the whole diagnosis; the rest measure the
    // false-alarm rate, which the candidate search does not touch.
    const auto r = run_insmc(fmt::format("gap --records {} --format json --max-effects 1 --seed {} --rank {}", records,
                                         1 + file, file == 0 ? "always" : "never"));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const bool u = significant_after(r.out, "gap"), p = significant_after(r.out, "pessimistic");
    unmodelled += u;
    pessimistic += p;
    if (u) fmt::print("{}\n", object_after(r.out, "gap"));
    fmt::print("file {:3d}: {:2d} runs, {:4.1f} deg, {:2g} Hz, {:2d} digits, interval {:2g} s: unmodelled {}, "
               "pessimistic {}\n",
               file, s.runs, s.site.latitude_rad / kDegToRad, s.rate_hz, s.digits, s.interval_s, u, p);
    std::filesystem::remove(csv);
  }
  const int bound = binomial_bound(files, alpha);
  fmt::print("{} files of a perfect sensor through import-imu: {} significant (unmodelled), {} pessimistic; "
             "at most {} unmodelled expected (P(more) < 1e-3 at alpha = {})\n",
             files, unmodelled, pessimistic, bound, alpha);
  EXPECT_LE(unmodelled, bound);
}

}  // namespace
}  // namespace insmc::testing
