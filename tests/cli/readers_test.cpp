// End-to-end: every reader's caps and messages through the built program
// (exit 2, one line on stderr naming file, line and key, input escaped).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

#include "lib/records/record_io.h"
#include "tests/cli/run_program.h"
#include "tests/unit/lib/imu/synthetic_imu.h"

namespace insmc::testing {
namespace {

int line_count(const std::string& s) { return static_cast<int>(std::count(s.begin(), s.end(), '\n')); }
std::string write(const TempDir& dir, const std::string& name, const std::string& text) {
  const std::string path = (dir.path() / name).string();
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

void expect_refused(const ProgramResult& r, const std::string& what) {
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_EQ(line_count(r.err), 1) << r.err;
  EXPECT_TRUE(has(r.err, what)) << "expected '" << what << "' in: " << r.err;
}

TEST(Readers, ConfigFromAnEndlessFileStopsAtTheCap) {
  expect_refused(run_insmc("params --config /dev/zero"),
                 "/dev/zero: cannot read the --config file: larger than 1 MiB, the most a --config file may hold");
}

TEST(Readers, ConfigThatIsADirectoryIsAnError) {
  TempDir dir;
  expect_refused(run_insmc("params --config " + dir.str()), "cannot read the --config file: it is a directory");
}

TEST(Readers, ConfigWithAByteOrderMarkIsRead) {
  TempDir dir;
  const auto r = run_insmc("params --config " + write(dir, "bom.ini", "\xEF\xBB\xBF" "format = csv\n"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_FALSE(has(r.out, "|")) << r.out.substr(0, 200);  // csv, not the markdown table
}

TEST(Readers, ConfigErrorsNameFileLineAndKey) {
  TempDir dir;
  const std::string ini = write(dir, "study.ini", "# study\nformat = csv\nfromat = json\n");
  expect_refused(run_insmc("params --config " + ini), ini + ":3: unknown option 'fromat'");
  const std::string twice = write(dir, "twice.ini", "format = csv\nformat = json\n");
  expect_refused(run_insmc("params --config " + twice), twice + ":2: format given twice (first on line 1)");
  const std::string bad = write(dir, "bad.ini", "leveling-gain = \x1b[2J" + std::string(5000, '7') + "\n");
  const auto r = run_insmc("check --bounds nowhere --config " + bad);
  expect_refused(r, bad + ":1: leveling-gain = '\\x1B[2J");
  EXPECT_TRUE(has(r.err, "\u2026(5004 bytes)'")) << r.err;
  EXPECT_FALSE(has(r.err, "\x1b")) << r.err;
}

TEST(Readers, BoundsOtherThanRmsAtMostAreRefused) {
  TempDir dir;
  for (const char* limit : {"rms_m>=5", "rms_km<=5"}) {
    const std::string path =
        write(dir, "b.txt", std::string("scheme=none system=2 axis=horizontal t_min=84 ") + limit + "\n");
    expect_refused(run_insmc("check --samples 3000 --bounds " + path),
                   path + ":1:47: limit '" + limit + "': expected METRIC_UNIT<=NUMBER or METRIC<=NUMBERUNIT");
  }
  const std::string twice = write(dir, "twice.txt", "scheme=none system=2 axis=x system=1 t_min=84 rms_m<=5\n");
  expect_refused(run_insmc("check --samples 3000 --bounds " + twice),
                 twice + ":1:29: system given twice on one line (first at column 13)");
  std::string times;
  for (int i = 0; i <= 100; ++i) times += "scheme=none system=1 axis=x t_min=" + std::to_string(i) + " rms_m<=5\n";
  const std::string many = write(dir, "times.txt", times);
  expect_refused(run_insmc("check --samples 3000 --bounds " + many), many + ":101:35: more than 100 distinct t_min");
}

TEST(Readers, ResumeFromADirectoryIsAnError) {
  TempDir dir;
  expect_refused(run_insmc("run --resume " + dir.str()), "--resume = " + dir.str() + ": cannot read the checkpoint: it is a directory");
}

/// A small valid record file with `extra` header lines and `rows`.
std::string record_text(const std::string& extra, const std::string& rows = "0,10,test,0,0,0,0,0,0\n0,20,nav,0,0,0,0,0,0\n") {
  return "# insmc-record v1\n# latitude_deg=45\n# system=1\n# test_duration_s=10\n# scheme=none\n" + extra +
         "run,t_s,phase,f_x,f_y,f_z,r_x,r_y,r_z\n" + rows;
}

TEST(Readers, GapNamesTheRecordHeaderNotAnOption) {
  TempDir dir;
  const std::string pulse = write(dir, "pulse.csv", record_text("# dv_pulse_mps=1e-300\n"));
  const auto r = run_insmc("gap --records " + pulse);
  expect_refused(r, pulse + ":6:16: header dv_pulse_mps = '1e-300': must be 0 (a continuous output) or in [1e-06, 10]");
  EXPECT_FALSE(has(r.err, "--dv-pulse")) << r.err;
  const std::string late = write(dir, "late.csv", record_text("", "0,10,test,0,0,0,0,0,0\n0,1e7,nav,0,0,0,0,0,0\n"));
  expect_refused(run_insmc("gap --records " + late), late + ":8:3: t_s = 10000000: must lie in [-172800, 172800]");
  const std::string tau = write(dir, "tau.csv", record_text("# filter_interval_s=1e-9\n"));
  expect_refused(run_insmc("gap --records " + tau), tau + ":6:21: header filter_interval_s = '1e-9': must be in");
}

TEST(Readers, GapCapsTheRunsOfAllItsFilesTogether) {
  TempDir dir;
  std::string rows;
  for (int run = 0; run < 150; ++run) rows += std::to_string(run) + ",10,test,0,0,0,0,0,0\n";
  const std::string a = write(dir, "a.csv", record_text("", rows));
  const std::string b = write(dir, "b.csv", record_text("", rows));
  expect_refused(run_insmc("gap --records " + a + " --records " + b),
                 "--records = " + b + ": 300 runs and 300 rows up to this file: the files of one diagnosis may hold at "
                 "most 200 runs");
}

std::string write_imu_csv(const TempDir& dir, const std::string& name, double gyro_x_dps = 0.0) {
  SyntheticSite site;
  site.latitude_rad = 51.08 * kDegToRad;
  ImuSamples s = synthetic_samples(site, 10.0, 100.0);
  for (std::size_t k = 0; k < s.size(); ++k) {  // the columns' units: deg/s and g
    s.gyro_b_radps[k] /= kDegToRad;
    s.accel_b_mps2[k] /= kGravityMps2;
  }
  std::string text = samples_csv(s, "gyro_x_dps,gyro_y_dps,gyro_z_dps,acc_x_g,acc_y_g,acc_z_g");
  if (gyro_x_dps != 0.0) {  // replace the first value of the third data line
    std::size_t at = 0;
    for (int i = 0; i < 3; ++i) at = text.find('\n', at) + 1;
    text.replace(at, text.find(',', at) - at, "1e200");
  }
  return write(dir, name, text);
}

const std::string kShort = " --rate 10Hz --latitude 51.08deg --align-duration 20s --test-duration 40s --nav-duration 30s --interval 10s";

TEST(Readers, ImportImuRefusesAnAbsurdGyroSampleWithFileAndLine) {
  TempDir dir;
  const std::string in = write_imu_csv(dir, "imu.csv", 1e200);
  const std::string out = (dir.path() / "r.csv").string();
  expect_refused(run_insmc("import-imu --input " + in + " --out " + out + kShort),
                 in + ":4:1: gyro_x_dps = '1e200' deg/s: |gyro| must be at most");
  EXPECT_FALSE(std::filesystem::exists(out));
}

TEST(Readers, ImportImuTakesAPathWithANewlineOrTrailingBlank) {
  TempDir dir;
  for (const std::string name : {"im\nu.csv", "imu.csv ", "im\x01u.csv"}) {
    const std::string in = write_imu_csv(dir, name);
    const std::string out = (dir.path() / "r.csv").string();
    const auto r = run_insmc("import-imu --input '" + in + "' --out " + out + kShort);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const RecordFile f = read_record_file(out);
    const std::string* source = f.header.find("imu.run0.source");
    ASSERT_NE(source, nullptr);
    EXPECT_EQ(source->find_first_of("\n\x01"), std::string::npos) << *source;
    EXPECT_NE(source->back(), ' ') << *source;
  }
}

TEST(Readers, ImportImuRefusesARunLongerThanARecordHolds) {
  TempDir dir;
  const std::string in = write_imu_csv(dir, "imu.csv");
  const std::string out = (dir.path() / "r.csv").string();
  expect_refused(run_insmc("import-imu --input " + in + " --out " + out +
                           " --rate 10Hz --latitude 51.08deg --align-duration 20s --test-duration 40s --nav-duration 50h"),
                 "--nav-duration = 180000s: the test run and the navigation together may last at most 48 h");
}

}  // namespace
}  // namespace insmc::testing
