// Values as a new user types them, end to end: every sweep value meets the
// single value's range check; a number and a unit are each read whole; a
// stream stops at its reader's cap without being held; times on a lattice
// never reach past its end. Each case ends with exit 0 or 2 (never a
// signal, never exit 3 or 134) within 60 s under 1 GB (run_limited: timeout
// and wait4's peak resident size).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "tests/cli/run_program.h"

namespace insmc::testing {
namespace {

namespace fs = std::filesystem;

constexpr long kMaxRssKb = 1L << 20;  // 1 GB
constexpr int kMaxSeconds = 60;

/// Exit 2 in one line naming `names`, within the limits.
void expect_refused(const std::string& args, const std::string& names) {
  const ProgramResult r = run_limited(args, kMaxSeconds);
  EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << args << "\n" << r.err;
  EXPECT_NE(r.err.find(names), std::string::npos) << args << "\n" << r.err;
  EXPECT_LT(r.peak_rss_kb, kMaxRssKb) << args;
}

/// Exit 0 within the limits.
void expect_done(const std::string& args) {
  const ProgramResult r = run_limited(args, kMaxSeconds);
  EXPECT_EQ(r.exit_code, 0) << args << "\n" << r.err;
  EXPECT_LT(r.peak_rss_kb, kMaxRssKb) << args;
}

/// A still IMU logging at 1 Hz for `seconds` (earth rate on the gyros at
/// latitude 51 deg with x north, gravity on z), with a time column.
std::string still_imu(const TempDir& dir, const std::string& name, int seconds) {
  const fs::path path = dir.path() / name;
  std::ofstream out(path);
  out << "t,gyro_x_dps,gyro_y_dps,gyro_z_dps,acc_x_g,acc_y_g,acc_z_g\n";
  const double w = 15.041 / 3600, lat = 51 * M_PI / 180;  // deg/s
  for (int k = 0; k <= seconds; ++k)
    out << fmt::format("{},{:.9f},{:.9f},{:.9f},{:.7f},{:.7f},-1\n", k, w * std::cos(lat) + 1e-6 * std::sin(k), 1e-6 * std::cos(k),
                       -w * std::sin(lat), 1e-5 * std::sin(0.1 * k), 1e-5 * std::cos(0.1 * k));
  return path.string();
}

TEST(HostileValues, EverySweepValueMeetsTheSingleValuesRangeCheck) {
  expect_refused("run --system 1 --latitude 91deg --samples 2 --quiet", "--latitude = 91deg: must lie within ±90deg");
  for (const char* list : {"45deg,91deg", "45deg,1000deg", "-91deg,0deg"})
    expect_refused(fmt::format("run --system 1 --latitude {} --samples 2 --quiet", list), "--latitude");
  // The alignment loops average over the swept value, in their own range
  // [0.1 s, 6 h] (a test run's average may be shorter).
  expect_refused("run --fidelity truth --alignment-time 10min --alignment-average 0.05s --samples 2 --quiet",
                 "--alignment-average");
  expect_refused("run --fidelity truth --alignment-time 10min --alignment-average 60s,0.05s --samples 2 --quiet",
                 "--alignment-average");
}

TEST(HostileValues, ANumberAndAUnitAreEachReadWhole) {
  TempDir dir;
  const std::string imu = still_imu(dir, "imu.csv", 600);
  // A time unit is a unit alone: these were read as 10 s, 1.5 s and 1000 s.
  for (const char* unit : {"0s", ".5s", "e3s", "1s", " s"})
    expect_refused(fmt::format("noise --input {} --time-column t --time-unit '{}'", imu, unit), "--time-unit");
  // A number is decimal: no hexadecimal, no blank before it.
  expect_refused("noise --input " + imu + " --rate 0x1p0Hz", "--rate = 0x1p0Hz: unknown unit 'x1p0Hz'");
  expect_refused("simulate --runs 1 --nav-duration 0x10s --out " + dir.str() + "/x.rec",
                 "--nav-duration = 0x10s: unknown unit 'x10s'");
  expect_refused("simulate --runs 1 --nav-duration ' 10min' --out " + dir.str() + "/x.rec", "--nav-duration");
  EXPECT_FALSE(fs::exists(dir.path() / "x.rec"));
  // The README's spellings of a random walk after 1 h, every one.
  for (const char* walk : {"0.03mpsprth", "0.03m/s/√h", "0.03m/s/sqrt(h)"})
    expect_done(fmt::format("simulate --runs 1 --nav-duration 10min --effect 'velocity_random_walk:velocity_1h={}' "
                            "--out {}/walk.rec",
                            walk, dir.str()));
  expect_done("simulate --runs 1 --nav-duration 10min --effect 'angle_random_walk:angle_1h=0.005deg/√h' --out " +
              dir.str() + "/angle.rec");
}

TEST(HostileValues, AnEndlessStreamStopsAtTheReadersCapUnheld) {
  // Once read whole into memory (2 GiB, 60 s) before the refusal.
  TempDir dir;
  expect_refused("noise --input /dev/zero --rate 100Hz", "an IMU CSV line may hold at most");
  expect_refused("import-imu --input /dev/zero --rate 100Hz --latitude 51deg --out " + dir.str() + "/zero.rec",
                 "an IMU CSV line may hold at most");
  EXPECT_FALSE(fs::exists(dir.path() / "zero.rec"));
  // A checkpoint is told by its first line, not after 1 GiB held.
  expect_refused("run --resume /dev/zero", "--resume = /dev/zero: not an insmc checkpoint file");
  expect_refused("run --from /dev/zero", "--from = /dev/zero: is not JSON");
}

TEST(HostileValues, TimesOnALatticeNeverPassItsEnd) {
  TempDir dir;
  // 48 h of navigation after the test run, 4608 ms apart: 37500 × 4.608 s
  // is 172800.00000000003 s in doubles, past the record's 48 h (once exit
  // 134 at the record writer).
  const std::string imu = still_imu(dir, "48h.csv", 48 * 3600 + 600);
  const std::string out = dir.str() + "/48h.rec";
  expect_done("import-imu --input " + imu + " --time-column t --latitude 51deg --test-duration 15min "
              "--nav-duration 2865min --interval 4608ms --noise off --out " + out);
  const std::string records = read_file(out);
  EXPECT_NE(records.find("\n0,172800,nav,"), std::string::npos) << "the last row on the run's end";
}

}  // namespace
}  // namespace insmc::testing
