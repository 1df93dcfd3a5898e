// The record reader's caps and physical ranges: each refused with
// FILE:LINE:COLUMN, the key or column, and the cap or range in the message.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "lib/common/input_error.h"
#include "lib/records/record.h"
#include "lib/records/record_io.h"

namespace insmc {
namespace {

std::string header(const std::vector<std::string>& extra = {}, const std::string& scheme = "none") {
  std::string out = "# insmc-record v1\n# latitude_deg=45\n# system=1\n# test_duration_s=900\n# scheme=" + scheme + "\n";
  for (const auto& e : extra) out += "# " + e + "\n";
  return out + "run,t_s,phase,f_x,f_y,f_z,r_x,r_y,r_z\n";
}

std::string error_of(const std::string& text) {
  try {
    parse_record_text(text, "runs.csv");
  } catch (const InputError& e) {
    return e.what();
  }
  return "(accepted)";
}

TEST(RecordCaps, GoodFileIsAccepted) {
  EXPECT_EQ(error_of(header({"dv_pulse_mps=0.03", "filter_interval_s=10"}) + "0,10,test,0,0,0,0,0,0\n"), "(accepted)");
}

TEST(RecordCaps, HeaderValuesOutsideTheirPhysicalRangeNameLineAndKey) {
  struct Case {
    std::string line, expected;
  };
  const std::vector<Case> cases = {
      {"dv_pulse_mps=1e-300", "runs.csv:6:16: header dv_pulse_mps = '1e-300': must be 0 (a continuous output) or in [1e-06, 10] (m/s)"},
      {"dv_pulse_mps=11", "header dv_pulse_mps = '11'"},
      {"position_resolution_m=1e-12", "header position_resolution_m = '1e-12': must be 0 (exact) or in [1e-06, 10000]"},
      {"filter_interval_s=0", "runs.csv:6:21: header filter_interval_s = '0': must be in [0.0001, 3600]"},
      {"filter_interval_s=1e9", "header filter_interval_s = '1e9'"},
      {"nav_start_s=1e12", "header nav_start_s = '1e12': must be in [0, 172800]"},
  };
  for (const Case& c : cases) {
    const std::string e = error_of(header({c.line}) + "0,10,test,0,0,0,0,0,0\n");
    EXPECT_NE(e.find(c.expected), std::string::npos) << c.line << ": " << e;
  }
  const std::string t = error_of(
      "# insmc-record v1\n# latitude_deg=45\n# system=1\n# test_duration_s=1e7\n# scheme=none\n"
      "run,t_s,phase,f_x,f_y,f_z,r_x,r_y,r_z\n0,10,test,0,0,0,0,0,0\n");
  EXPECT_NE(t.find("runs.csv:4:19: header test_duration_s = '1e7': must be in (0, 172800]"), std::string::npos) << t;
}

// The raw-sensor stage's keys feed the null of imported records: a corrupt
// one is refused rather than read as an absent noise term.
TEST(RecordCaps, RawStageKeysMustBeNonNegativeNumbers) {
  const std::string rows = "0,10,test,0,0,0,0,0,0\n";
  const std::string key = "imu.noise.gyro_x.angle_random_walk_si";
  const std::string nan = error_of(header({"imu.noise=on", key + "=nan"}) + rows);
  EXPECT_NE(nan.find("runs.csv:7:"), std::string::npos) << nan;
  EXPECT_NE(nan.find("header " + key + " = 'nan': must be a finite number"), std::string::npos) << nan;
  const std::string negative = error_of(header({"imu.noise=on", key + "=-5"}) + rows);
  EXPECT_NE(negative.find("header " + key + " = '-5': must be a non-negative number"), std::string::npos) << negative;
  const std::string flag = error_of(header({"imu.noise=on", "imu.noise.gyro_x.warm_up_excluded=2"}) + rows);
  EXPECT_NE(flag.find("must be 0 or 1"), std::string::npos) << flag;
  // Large is not corrupt: the diagnosis says such a sensor is beyond any
  // synthesis and keeps the model's null.
  EXPECT_EQ(error_of(header({"imu.noise=on", key + "=1e300"}) + rows),
            "(accepted)");
  EXPECT_EQ(error_of(header({"imu.noise=skipped: fewer than 300 samples"}) + rows), "(accepted)");
}

TEST(RecordCaps, InconsistentHeaderBlamesTheKeysLine) {
  const std::string tau = error_of(header({"filter_interval_s=1000"}) + "0,10,test,0,0,0,0,0,0\n");
  EXPECT_NE(tau.find("runs.csv:6:1: header filter_interval_s: filter_interval_s = 1000: must be no longer than "
                     "test_duration_s = 900"),
            std::string::npos)
      << tau;
  const std::string whole = error_of(header({"filter_interval_s=7"}, "5.2") + "0,10,test,0,0,0,0,0,0\n");
  EXPECT_NE(whole.find("runs.csv:6:1: header filter_interval_s"), std::string::npos) << whole;
  EXPECT_NE(whole.find("whole number"), std::string::npos) << whole;
  const std::string nav = error_of(header({}, "5.1.1") + "0,10,test,0,0,0,0,0,0\n");
  EXPECT_NE(nav.find("header nav_start_s: missing: records after scheme 5.1.1"), std::string::npos) << nav;
  const std::string before = error_of(header({"nav_start_s=100"}, "5.1.1") + "0,10,test,0,0,0,0,0,0\n");
  EXPECT_NE(before.find("runs.csv:6:1: header nav_start_s: nav_start_s = 100: must be > test_duration_s"),
            std::string::npos)
      << before;
}

TEST(RecordCaps, RowTimesAreCappedAtTheLongestRun) {
  for (const char* t : {"1e7", "1e12"}) {
    const std::string e = error_of(header() + fmt::format("0,{},nav,0,0,0,0,0,0\n", t));
    EXPECT_NE(e.find(fmt::format("runs.csv:7:3: t_s = {}: must lie in [-172800, 172800] (a run lasts at most 48 h)",
                                 std::stod(t))),
              std::string::npos)
        << e;
  }
  EXPECT_NE(error_of(header() + "0,-1e6,align,0,0,0,,,\n0,10,test,0,0,0,0,0,0\n").find("t_s = -1000000: must lie in"),
            std::string::npos);
}

TEST(RecordCaps, RowValuesAreCapped) {
  EXPECT_NE(error_of(header() + "0,10,test,1e7,0,0,0,0,0\n").find("runs.csv:7:11: f_x = 10000000: |f| must be at most 1000000"),
            std::string::npos);
  EXPECT_NE(error_of(header() + "0,10,test,0,0,0,0,1e300,0\n").find("r_y = 1e+300: |r| must be at most 1e+16"),
            std::string::npos);
}

TEST(RecordCaps, TooManyRunsAreRefused) {
  std::string text = header();
  for (std::size_t run = 0; run <= kMaxRecordRuns; ++run) text += fmt::format("{},10,test,0,0,0,0,0,0\n", run);
  const std::string e = error_of(text);
  EXPECT_NE(e.find(fmt::format("runs.csv:{}:1: run {} is run number {} of the file: a record file may hold at most {} runs",
                               7 + kMaxRecordRuns, kMaxRecordRuns, kMaxRecordRuns + 1, kMaxRecordRuns)),
            std::string::npos)
      << e;
  // One fewer is accepted.
  text.resize(text.rfind(fmt::format("{},", kMaxRecordRuns)));
  EXPECT_EQ(error_of(text), "(accepted)");
}

TEST(RecordCaps, TooLongALineIsRefusedWithoutEchoingIt) {
  const std::string e = error_of(header({"note=" + std::string(kMaxRecordLineBytes, 'x')}));
  EXPECT_NE(e.find(fmt::format("runs.csv:6:{}: line of {} bytes: a record line may hold at most {} bytes",
                               kMaxRecordLineBytes + 1, kMaxRecordLineBytes + 7, kMaxRecordLineBytes)),
            std::string::npos)
      << e.substr(0, 200);
  EXPECT_LT(e.size(), 200u);
}

TEST(RecordCaps, BinaryBytesAndHugeValuesAreEscapedAndCut) {
  const std::string e = error_of("# insmc-record v1\n# latitude_deg=45\n# system=1\n# test_duration_s=900\n# scheme=\xff\xfe" +
                                 std::string(1000, 'y') + "\nrun,t_s,phase,f_x,f_y,f_z,r_x,r_y,r_z\n0,10,test,0,0,0,0,0,0\n");
  EXPECT_EQ(e.find('\xff'), std::string::npos) << e;
  EXPECT_NE(e.find("runs.csv:5:10: header scheme = '\\xFF\\xFE" + std::string(38, 'y') + "\u2026(1002 bytes)': must be one of"),
            std::string::npos)
      << e;
}

TEST(RecordCaps, ControlBytesInsideAHeaderValueAreRefused) {
  // Found by tests/fuzz (regressions/records/header_value_with_lone_cr): the
  // reader took a lone CR inside a value that the writer then refused.
  const std::string e = error_of(header({"vendor=mca\re"}) + "0,10,test,0,0,0,0,0,0\n");
  EXPECT_NE(e.find("runs.csv:6:13: control character '\\r' in the header line '# vendor=mca\\re'"), std::string::npos)
      << e;
  EXPECT_NE(error_of(header({std::string("ven\0dor=x", 9)}) + "0,10,test,0,0,0,0,0,0\n").find("runs.csv:6:6: control character '\\x00'"),
            std::string::npos);
  EXPECT_EQ(error_of(header({"vendor=a\tb"}) + "0,10,test,0,0,0,0,0,0\n"), "(accepted)");
}

TEST(RecordCaps, TheWriterKeepsWhatTheReaderAccepts) {
  RecordFile f = parse_record_text(header({"dv_pulse_mps=1e-6", "filter_interval_s=1e-4"}) + "0,10,test,0,0,0,0,0,0\n",
                                   "runs.csv");
  EXPECT_EQ(parse_record_text(write_record_file(f), "again.csv"), f);
}

}  // namespace
}  // namespace insmc
