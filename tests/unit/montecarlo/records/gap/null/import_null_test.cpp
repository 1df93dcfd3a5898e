// The null through the import (montecarlo/records/gap/null/import_null.h): which
// headers it accepts, and the importer's convention it must carry, derived
// by hand. Accelerometer white noise N on a level sensor: each f row is the
// noise's mean over its window in a', less, on the horizontal axes, its mean
// over the alignment window (leveling turns that mean into a tilt, whose g·θ
// cancels it); the vertical keeps it. So the mean of a run's f rows over
// test and navigation (windows that tile [0, D]) has variance
//   N²/D + N²/T_align  horizontally,  N²/D  vertically.
#include "montecarlo/records/gap/null/import_null.h"

#include <boost/math/distributions/chi_squared.hpp>
#include <cmath>
#include <gtest/gtest.h>

namespace insmc::gap {
namespace {

constexpr double kAlignS = 300, kTestS = 300, kNavS = 300, kIntervalS = 10;

RecordFile imported_file(double accel_white) {
  RecordFile f;
  f.header = RecordHeader::make(45.0, System::kTheodolite, kTestS, Scheme::kNone);
  f.header.set("filter_interval_s", kIntervalS);
  f.header.set("imu.align_duration_s", kAlignS);
  f.header.set("imu.nav_duration_s", kNavS);
  f.header.set("imu.noise", std::string("on"));
  f.header.set("imu.noise.sample_interval_s", 0.1);
  for (const char* c : {"gyro_x", "gyro_y", "gyro_z", "accel_x", "accel_y", "accel_z"})
    f.header.set(std::string("imu.noise.") + c + ".equivalent_si", 1e-9);
  for (const char* c : {"accel_x", "accel_y", "accel_z"})
    f.header.set(std::string("imu.noise.") + c + ".velocity_random_walk_si", accel_white);
  RecordRun run;
  run.id = 0;
  for (int k = 1; k * kIntervalS <= kTestS + kNavS + 1e-9; ++k) {
    RecordRow row;
    row.t_s = k * kIntervalS;
    row.phase = row.t_s <= kTestS ? Phase::kTest : Phase::kNav;
    row.f_mps2 = {0.0, 0.0, 0.0};
    row.r_ap_m = Eigen::Vector3d::Zero();
    run.rows.push_back(row);
  }
  f.runs.push_back(run);
  return f;
}

TEST(ImportNull, LevelingTakesTheAlignmentMeanOffTheHorizontalAccelerometers) {
  const double N = 1e-3;  // m/s/√s
  const RecordFile file = imported_file(N);
  std::vector<std::string> statements;
  const std::optional<ImportNull> import = import_null_for(file, statements);
  ASSERT_TRUE(import) << (statements.empty() ? "" : statements.front());
  const int runs = 60;
  Eigen::Vector3d sum = Eigen::Vector3d::Zero(), sum2 = Eigen::Vector3d::Zero();
  for (int j = 0; j < runs; ++j) {
    RecordRun r = file.runs.front();
    add_import_noise(r, file.header, 0, *import, 11, static_cast<std::uint64_t>(j));
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    for (const RecordRow& row : r.rows)
      for (int c = 0; c < 3; ++c) mean[c] += *row.f_mps2[c] / static_cast<double>(r.rows.size());
    sum += mean;
    sum2 += mean.cwiseProduct(mean);
  }
  const double D = kTestS + kNavS;
  const double expected[3] = {N * N * (1 / D + 1 / kAlignS), N * N * (1 / D + 1 / kAlignS), N * N / D};
  // The sample variance over runs: (runs − 1) s²/σ² ~ χ²(runs − 1), two-sided at 1e-3 per axis.
  const boost::math::chi_squared chi(runs - 1);
  for (int c = 0; c < 3; ++c) {
    const double s2 = (sum2[c] - sum[c] * sum[c] / runs) / (runs - 1);
    const double ratio = (runs - 1) * s2 / expected[c];
    EXPECT_GT(ratio, boost::math::quantile(chi, 5e-4)) << "axis " << c << " s2 " << s2 << " expected " << expected[c];
    EXPECT_LT(ratio, boost::math::quantile(chi, 1 - 5e-4)) << "axis " << c << " s2 " << s2 << " expected " << expected[c];
  }
}

TEST(ImportNull, SameSeedAndRunSameRows) {
  const RecordFile file = imported_file(1e-3);
  std::vector<std::string> statements;
  const auto import = import_null_for(file, statements);
  ASSERT_TRUE(import);
  RecordRun a = file.runs.front(), b = a, c = a;
  add_import_noise(a, file.header, 0, *import, 5, 3);
  add_import_noise(b, file.header, 0, *import, 5, 3);
  add_import_noise(c, file.header, 0, *import, 5, 4);
  EXPECT_EQ(*a.rows[7].f_mps2[0], *b.rows[7].f_mps2[0]);
  EXPECT_NE(*a.rows[7].f_mps2[0], *c.rows[7].f_mps2[0]);
}

TEST(ImportNull, SaysWhyWhenItCannotGoThroughTheImport) {
  std::vector<std::string> statements;
  RecordFile plain = imported_file(1e-3);
  plain.header = RecordHeader::make(45.0, System::kTheodolite, kTestS, Scheme::kNone);
  EXPECT_FALSE(import_null_for(plain, statements));  // not imported: nothing to say
  EXPECT_TRUE(statements.empty());

  RecordFile absurd = imported_file(1e300);
  EXPECT_FALSE(import_null_for(absurd, statements));
  ASSERT_EQ(statements.size(), 1u);
  EXPECT_NE(statements.back().find("accel_x"), std::string::npos) << statements.back();

  RecordFile off_grid = imported_file(1e-3);
  off_grid.runs.front().rows[3].t_s += 0.5;
  EXPECT_FALSE(import_null_for(off_grid, statements));
  ASSERT_EQ(statements.size(), 2u);
  EXPECT_NE(statements.back().find("t = 40.5 s"), std::string::npos) << statements.back();

  RecordFile no_align = imported_file(1e-3);
  std::erase_if(no_align.header.entries, [](const HeaderEntry& e) { return e.key == "imu.align_duration_s"; });
  EXPECT_FALSE(import_null_for(no_align, statements));
  ASSERT_EQ(statements.size(), 3u);
  EXPECT_NE(statements.back().find("imu.align_duration_s"), std::string::npos) << statements.back();
}

}  // namespace
}  // namespace insmc::gap
