// End-to-end tests of `insmc import-imu`: a tiny synthetic CSV in the ADIS
// layout round-trips into a record file that read_record_file accepts, runs
// come from several inputs or from splitting one, and each kind of bad input
// gives exit 2, one line naming the field or value, and no output file.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>

#include "lib/records/record_io.h"
#include "tests/cli/run_program.h"
#include "tests/unit/lib/imu/synthetic_imu.h"

namespace insmc::testing {
namespace {

int line_count(const std::string& s) { return static_cast<int>(std::count(s.begin(), s.end(), '\n')); }

// Short phases keep the files tiny: 20 s alignment + 60 s test + 60 s nav.
const std::string kShort = " --align-duration 20s --test-duration 1min --nav-duration 60s --interval 10s";

/// A perfect stationary sensor at 51.08°, heading 30°, in the ADIS units
/// (deg/s, g) and column names, 10 Hz, `duration_s` long.
std::string write_adis_csv(const TempDir& dir, const std::string& name, double duration_s) {
  SyntheticSite site;
  site.latitude_rad = 51.08 * kDegToRad;
  site.heading_rad = 30.0 * kDegToRad;
  ImuSamples s = synthetic_samples(site, 10.0, duration_s);
  for (std::size_t k = 0; k < s.size(); ++k) {
    s.gyro_b_radps[k] /= kDegToRad;
    s.accel_b_mps2[k] /= kGravityMps2;
  }
  const std::string path = (dir.path() / name).string();
  std::ofstream(path) << samples_csv(s, "gyro_x_dps,gyro_y_dps,gyro_z_dps,acc_x_g,acc_y_g,acc_z_g");
  return path;
}

TEST(ImportImu, TwoInputsRoundTripIntoRecords) {
  TempDir dir;
  const std::string a = write_adis_csv(dir, "a.csv", 140.0), b = write_adis_csv(dir, "b.csv", 150.0);
  const std::string out = (dir.path() / "records.csv").string();
  const auto r = run_insmc("import-imu --input " + a + " --input " + b +
                           " --rate 10Hz --gyro-unit deg/s --accel-unit g --latitude 51.08deg --azimuth 30deg" +
                           kShort + " --out " + out);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;  // quiet on success
  const RecordFile file = read_record_file(out);
  EXPECT_DOUBLE_EQ(file.header.latitude_deg(), 51.08);
  EXPECT_EQ(file.header.system(), System::kTheodolite);
  EXPECT_DOUBLE_EQ(file.header.test_duration_s(), 60.0);
  EXPECT_EQ(file.header.scheme(), Scheme::kNone);
  EXPECT_EQ(file.header.dv_pulse_mps(), 0.0);
  ASSERT_NE(file.header.find("filter_interval_s"), nullptr);
  EXPECT_EQ(*file.header.find("filter_interval_s"), "10");
  ASSERT_NE(file.header.find("imu.run1.source"), nullptr);
  EXPECT_EQ(*file.header.find("imu.run1.source"), b);
  ASSERT_NE(file.header.find("imu.run0.gyro_bias_x_radps"), nullptr);
  EXPECT_LT(std::abs(std::stod(*file.header.find("imu.run0.gyro_bias_x_radps"))), 1e-12);
  ASSERT_EQ(file.runs.size(), 2u);
  for (const RecordRun& run : file.runs) {
    ASSERT_EQ(run.rows.size(), 12u);  // 10 s … 120 s
    EXPECT_EQ(run.rows[5].phase, Phase::kTest);  // t = 60 s = T
    EXPECT_EQ(run.rows[6].phase, Phase::kNav);
    for (const RecordRow& row : run.rows) {
      EXPECT_LT(row.r_ap_m->norm(), 1e-3) << row.t_s;
      ASSERT_TRUE(row.has_f());
      EXPECT_LT(std::abs(*row.f_mps2[0]) + std::abs(*row.f_mps2[1]) + std::abs(*row.f_mps2[2]), 1e-8);
    }
  }
}

TEST(ImportImu, SplitCutsOneFileIntoConsecutiveRuns) {
  TempDir dir;
  const std::string a = write_adis_csv(dir, "long.csv", 300.0);  // two runs of 140 s, 20 s left over
  const std::string out = (dir.path() / "split.csv").string();
  const auto r = run_insmc("import-imu --input " + a + " --rate 10Hz --latitude 51.08deg --azimuth 30deg --runs-from split" +
                           kShort + " --out " + out);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const RecordFile file = read_record_file(out);
  ASSERT_EQ(file.runs.size(), 2u);
  ASSERT_NE(file.header.find("imu.run1.switch_time_s"), nullptr);
  EXPECT_EQ(*file.header.find("imu.run1.switch_time_s"), "160");
  EXPECT_EQ(*file.header.find("imu.runs_from"), "split");
}

TEST(ImportImu, TimeColumnCustomColumnsAndSiUnits) {
  TempDir dir;
  SyntheticSite site;
  site.latitude_rad = -33.9 * kDegToRad;
  const ImuSamples s = synthetic_samples(site, 20.0, 140.0);
  std::string text = "t_ms,ax,ay,az,wx,wy,wz\n";
  for (std::size_t k = 0; k < s.size(); ++k) {
    const Vec3 &w = s.gyro_b_radps[k], &f = s.accel_b_mps2[k];
    text += fmt::format("{},{},{},{},{},{},{}\n", 5000.0 + 1e3 * s.t_s[k], f.x(), f.y(), f.z(), w.x(), w.y(), w.z());
  }
  const std::string in = (dir.path() / "log.csv").string(), out = (dir.path() / "r.csv").string();
  std::ofstream(in) << text;
  const auto r = run_insmc("import-imu --input " + in +
                           " --time-column t_ms --time-unit ms --gyro-columns wx,wy,wz --accel-columns ax,ay,az"
                           " --gyro-unit rad/s --accel-unit m/s2 --latitude -33.9deg" +
                           kShort + " --out " + out);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const RecordFile file = read_record_file(out);
  ASSERT_EQ(file.runs.size(), 1u);
  EXPECT_EQ(*file.header.find("imu.time_column"), "t_ms");
  for (const RecordRow& row : file.runs[0].rows) EXPECT_LT(row.r_ap_m->norm(), 1e-3) << row.t_s;
  const auto bad = run_insmc("import-imu --input " + in + " --time-column t_ms --time-unit fortnight --latitude 0deg" +
                             kShort + " --out " + out + "2");
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("--time-unit = fortnight"), std::string::npos) << bad.err;
}

TEST(ImportImu, BadInputGivesOneLineExitTwoAndNoOutput) {
  TempDir dir;
  const std::string good = write_adis_csv(dir, "good.csv", 140.0);
  const std::string text_value = (dir.path() / "text.csv").string();
  std::ofstream(text_value) << "gyro_x_dps,gyro_y_dps,gyro_z_dps,acc_x_g,acc_y_g,acc_z_g\n0,0,0,0,0,-1\n0,0,x1,0,0,-1\n";
  const std::string gz = (dir.path() / "run.csv.gz").string();
  std::ofstream(gz, std::ios::binary) << "\x1f\x8b\x08" << std::string(16, 'z');
  struct Case {
    std::string args, names;
  };
  const std::string base = " --rate 10Hz --latitude 51.08deg" + kShort;
  const Case cases[] = {
      {"--input " + good + base + " --gyro-columns wx,wy,wz", "missing column(s) 'wx' (--gyro-columns)"},
      {"--input " + good + base + " --gyro-unit rpm", "--gyro-unit = rpm"},
      {"--input " + good + base + " --accel-unit mg", "--accel-unit = mg"},
      {"--input " + text_value + base, "text.csv:3:5: gyro_z_dps = 'x1': not a number"},
      {"--input " + good + " --rate 0Hz --latitude 51.08deg" + kShort, "--rate = 0Hz"},
      {"--input " + good + " --rate 0 --latitude 51.08deg" + kShort, "--rate = 0"},
      {"--input " + good + " --latitude 51.08deg" + kShort, "--rate"},
      {"--input " + good + " --rate 10Hz" + kShort, "--latitude"},
      {"--input " + good + " --rate 10Hz --latitude 51.08deg --align-duration 20s --nav-duration 90min",
       "shorten --nav-duration"},
      {"--input " + good + base + " --gyro-bias drop", "--gyro-bias = drop"},
      {"--input " + good + base + " --runs-from halves", "--runs-from = halves"},
      {"--input " + gz + base, "gzip-compressed"},
      {"--input " + (dir.path() / "missing.csv").string() + base, "cannot open"},
      {base, "--input"},
  };
  for (const Case& c : cases) {
    const auto out = dir.path() / "out.csv";
    const auto r = run_insmc("import-imu " + c.args + " --out " + out.string());
    EXPECT_EQ(r.exit_code, 2) << c.args << "\n" << r.err;
    EXPECT_EQ(line_count(r.err), 1) << c.args << "\n" << r.err;
    EXPECT_NE(r.err.find(c.names), std::string::npos) << c.args << "\n" << r.err;
    EXPECT_FALSE(std::filesystem::exists(out)) << c.args;
  }
  const auto help = run_insmc("import-imu --help");
  EXPECT_EQ(help.exit_code, 0);
  EXPECT_NE(help.out.find("usage: insmc import-imu"), std::string::npos);
}

}  // namespace
}  // namespace insmc::testing
