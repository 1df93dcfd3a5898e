// The IMU reader's caps and physical ranges: sample magnitude, rate, time,
// line length; escaped echoes.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <string>

#include "tests/unit/input_error_of.h"
#include "lib/imu/imu_samples.h"

namespace insmc {
namespace {

constexpr const char* kHeader = "gyro_x_dps,gyro_y_dps,gyro_z_dps,acc_x_g,acc_y_g,acc_z_g\n";

ImuCsvOptions at(double rate_hz) {
  ImuCsvOptions o;
  o.rate_hz = rate_hz;
  return o;
}

std::string error_of(const std::string& text, const ImuCsvOptions& o) {
  try {
    parse_imu_csv(text, "imu.csv", o);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(accepted)";
}

std::string with_rows(const std::string& rows) {
  std::string text = kHeader;
  return text + rows;
}

TEST(ImuCaps, SampleMagnitudesAreCapped) {
  const std::string gyro = error_of(with_rows("0,0,0,0,0,-1\n1e200,0,0,0,0,-1\n"), at(100));
  EXPECT_NE(gyro.find("imu.csv:3:1: gyro_x_dps = '1e200' deg/s: |gyro| must be at most 5729.58 deg/s (100 rad/s)"),
            std::string::npos)
      << gyro;
  const std::string accel = error_of(with_rows("0,0,0,0,0,-1\n0,0,0,0,0,-2000\n"), at(100));
  EXPECT_NE(accel.find("imu.csv:3:11: acc_z_g = '-2000' g: |accel| must be at most 1019.72 g (10000 m/s2)"),
            std::string::npos)
      << accel;
  EXPECT_EQ(error_of(with_rows("5000,0,0,0,0,-1\n0,0,0,0,0,-400\n"), at(100)), "(accepted)");
}

TEST(ImuCaps, RateIsCapped) {
  EXPECT_NE(error_of(with_rows("0,0,0,0,0,-1\n0,0,0,0,0,-1\n"), at(1e-300)).find("--rate = 1e-300Hz: must lie in [1Hz, 100kHz]"),
            std::string::npos);
  EXPECT_NE(error_of(with_rows("0,0,0,0,0,-1\n0,0,0,0,0,-1\n"), at(1e6)).find("must lie in [1Hz, 100kHz]"),
            std::string::npos);
  try {
    parse_rate_hz("1e-300Hz", "--rate");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("--rate = 1e-300Hz: must lie in [1Hz, 100kHz]"), std::string::npos) << e.what();
  }
  EXPECT_EQ(parse_rate_hz("100kHz", "--rate"), 1e5);
}

TEST(ImuCaps, TimesAreCapped) {
  ImuCsvOptions o;
  o.time_column = "t";
  const std::string header = "t,gyro_x_dps,gyro_y_dps,gyro_z_dps,acc_x_g,acc_y_g,acc_z_g\n";
  const std::string far = error_of(header + "0,0,0,0,0,0,-1\n1e12,0,0,0,0,0,-1\n", o);
  EXPECT_NE(far.find("imu.csv:3:1: t = '1e12': a time must lie within ±10000000000 s"), std::string::npos) << far;
  const std::string long_file = error_of(header + "0,0,0,0,0,0,-1\n2e6,0,0,0,0,0,-1\n", o);
  EXPECT_NE(long_file.find("imu.csv:3:1: sample at 2000000 s after the first: an IMU file may cover at most 1209600 s"),
            std::string::npos)
      << long_file;
  // Unix time stamps are fine.
  EXPECT_EQ(error_of(header + "1.7e9,0,0,0,0,0,-1\n1.70000001e9,0,0,0,0,0,-1\n", o), "(accepted)");
}

TEST(ImuCaps, LongLinesAreRefusedAndValuesEscaped) {
  const std::string e = error_of(with_rows("0,0,0,0,0," + std::string(kMaxImuLineBytes, '1') + "\n"), at(100));
  EXPECT_NE(e.find(fmt::format("imu.csv:2:{}: line of {} bytes: an IMU CSV line may hold at most {} bytes",
                               kMaxImuLineBytes + 1, kMaxImuLineBytes + 10, kMaxImuLineBytes)),
            std::string::npos)
      << e.substr(0, 300);
  const std::string bad = error_of(with_rows("0,0,0,0,0,\x1b[2J" + std::string(500, 'z') + "\n"), at(100));
  EXPECT_EQ(bad.find('\x1b'), std::string::npos) << bad;
  EXPECT_NE(bad.find("acc_z_g = '\\x1B[2J"), std::string::npos) << bad;
  EXPECT_NE(bad.find("\u2026(504 bytes)'"), std::string::npos) << bad;
}

TEST(ImuCaps, ColumnNamesWithControlBytesOrBlanksAtTheEndsAreRefused) {
  ImuCsvOptions o = at(100);
  o.gyro_columns[0] = "gx ";
  ASSERT_TRUE(test::thrown_by([&] { validate(o); }).has_value());
  EXPECT_NE(std::string(test::thrown_by([&] { validate(o); })->what()).find("cannot start or end with a blank"), std::string::npos)
      << test::thrown_by([&] { validate(o); })->what();
  o.gyro_columns[0] = "g\x01x";
  EXPECT_NE(std::string(test::thrown_by([&] { validate(o); })->what()).find("--gyro-columns = g\\x01x: a column name cannot contain control"),
            std::string::npos)
      << test::thrown_by([&] { validate(o); })->what();
  o.gyro_columns[0] = " gx";
  EXPECT_TRUE(test::thrown_by([&] { validate(o); }).has_value());
}

}  // namespace
}  // namespace insmc
