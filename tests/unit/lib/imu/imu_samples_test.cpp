// Reading IMU CSV files: units, column order, time sources, the accepted
// forms, and one case per kind of bad input (one-line message naming file,
// line, column and field).
#include "tests/unit/input_error_of.h"
#include "lib/imu/imu_samples.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "lib/units/units.h"

namespace insmc {
namespace {

ImuCsvOptions adis_at(double rate_hz) {
  ImuCsvOptions o;  // the ADIS16405 column names, deg/s and g
  o.rate_hz = rate_hz;
  return o;
}

constexpr const char* kAdisHeader = "gyro_x_dps,gyro_y_dps,gyro_z_dps,acc_x_g,acc_y_g,acc_z_g\n";

/// The InputError message of parsing `text`, or "" when it parses.
std::string error_of(const std::string& text, const ImuCsvOptions& o) {
  try {
    parse_imu_csv(text, "imu.csv", o);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(ImuSamples, ReadsTheAdisLayoutInSi) {
  std::string text = kAdisHeader;  // (not std::string + literal: GCC 12's -Warray-bounds false positive)
  text += "0.40,-0.45,0.05,-0.00333,0.00000,-1.01667\n0.35,-0.40,0.00,0.00000,0.00333,-1.01333\n";
  const ImuSamples s = parse_imu_csv(text, "imu.csv", adis_at(100.0));
  ASSERT_EQ(s.size(), 2u);
  EXPECT_EQ(s.source, "imu.csv");
  EXPECT_DOUBLE_EQ(s.t_s[1], 0.01);
  EXPECT_DOUBLE_EQ(s.end_s(1), 0.02);
  EXPECT_DOUBLE_EQ(s.covered_s(), 0.02);
  EXPECT_DOUBLE_EQ(s.gyro_b_radps[0].x(), 0.40 * kDegToRad);
  EXPECT_DOUBLE_EQ(s.accel_b_mps2[0].z(), -1.01667 * kGravityMps2);
}

TEST(ImuSamples, ColumnsInAnyOrderTimeColumnAndLenientForm) {
  ImuCsvOptions o;
  o.gyro_columns = {"wx", "wy", "wz"};
  o.accel_columns = {"fx", "fy", "fz"};
  o.gyro_unit = GyroUnit::kDegPerH;
  o.accel_unit = AccelUnit::kMps2;
  o.time_column = "time_ms";
  o.time_unit_s = 1e-3;
  const std::string text =
      "\xEF\xBB\xBF# exported by a logger\r\n"
      "time_ms, fz, fy, fx, wz, wy, wx, temp\r\n"
      "\r\n"
      "1000, -9.8, 0.1, 0.2, 15, 0, -15, 25.0\r\n"
      "# a comment between rows\n"
      "1020, -9.7, 0.1, 0.2, 15, 0, -15, 25.1\n";
  const ImuSamples s = parse_imu_csv(text, "log.csv", o);
  ASSERT_EQ(s.size(), 2u);
  EXPECT_DOUBLE_EQ(s.t_s[0], 0.0);  // relative to the first sample
  EXPECT_NEAR(s.t_s[1], 0.02, 1e-15);
  EXPECT_DOUBLE_EQ(s.accel_b_mps2[1].z(), -9.7);
  EXPECT_DOUBLE_EQ(s.accel_b_mps2[0].x(), 0.2);
  EXPECT_DOUBLE_EQ(s.gyro_b_radps[0].x(), -15.0 * kDegphToRadps);
}

TEST(ImuSamples, EachKindOfBadInputNamesFileLineColumnAndField) {
  const std::string h = kAdisHeader;
  const ImuCsvOptions o = adis_at(100.0);
  struct Case {
    std::string text, expected;
  };
  const Case cases[] = {
      {"gyro_x_dps,gyro_y_dps,acc_x_g,acc_y_g,acc_z_g\n1,2,3,4,5\n",
       "imu.csv:1:1: missing column(s) 'gyro_z_dps' (--gyro-columns)"},
      {h + "0,0,0,0,0,-1\n0,0,abc,0,0,-1\n", "imu.csv:3:5: gyro_z_dps = 'abc': not a number"},
      {h + "0,0,0,0,0,-1\n0,0,0,0,nan,-1\n", "imu.csv:3:9: acc_y_g = 'nan': not finite"},
      {h + "0,0,0,0,0,-1\n0,0,0,0,0\n", "imu.csv:3:10: 5 fields, but the header (line 1) has 6"},
      {h + "0,0,0,0,0,-1\n", "imu.csv: 1 data row(s) after the header (line 1): at least 2 samples"},
      {"# nothing\n", "imu.csv: no header line"},
      {"gyro_x_dps,gyro_x_dps,gyro_y_dps,gyro_z_dps,acc_x_g,acc_y_g,acc_z_g\n",
       "imu.csv:1:12: duplicate column 'gyro_x_dps'"},
  };
  for (const Case& c : cases) {
    const std::string message = error_of(c.text, o);
    EXPECT_EQ(message.rfind(c.expected, 0), 0u) << "got: " << message << "\nexpected prefix: " << c.expected;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
  ImuCsvOptions timed = o;
  timed.rate_hz = 0.0;
  timed.time_column = "t";
  const std::string message =
      error_of("t,gyro_x_dps,gyro_y_dps,gyro_z_dps,acc_x_g,acc_y_g,acc_z_g\n0.5,0,0,0,0,0,-1\n0.5,0,0,0,0,0,-1\n",
               timed);
  EXPECT_EQ(message.rfind("imu.csv:3:1: t = '0.5': time must increase strictly (line 2 has 0.5)", 0), 0u) << message;
}

TEST(ImuSamples, OptionsUnitsAndRatesAreChecked) {
  ImuCsvOptions o;
  ASSERT_TRUE(test::thrown_by([&] { validate(o); }).has_value());  // no rate and no time column
  EXPECT_EQ(test::thrown_by([&] { validate(o); })->field(), "--rate");
  o.rate_hz = 100.0;
  EXPECT_FALSE(test::thrown_by([&] { validate(o); }).has_value());
  o.time_column = "t";
  EXPECT_EQ(test::thrown_by([&] { validate(o); })->field(), "--rate");  // both given
  o = adis_at(100.0);
  o.accel_columns[0] = "gyro_x_dps";
  EXPECT_EQ(test::thrown_by([&] { validate(o); })->field(), "--accel-columns");

  EXPECT_DOUBLE_EQ(parse_rate_hz("100Hz", "--rate"), 100.0);
  EXPECT_DOUBLE_EQ(parse_rate_hz("0.2kHz", "--rate"), 200.0);
  for (const char* bad : {"0Hz", "-5Hz", "100", "100rpm", "Hz", "infHz"}) {
    try {
      parse_rate_hz(bad, "--rate");
      ADD_FAILURE() << bad << " accepted";
    } catch (const InputError& e) {
      EXPECT_EQ(e.field(), "--rate") << bad;
      EXPECT_EQ(e.value(), bad);
    }
  }
  EXPECT_EQ(parse_gyro_unit("rad/s", "--gyro-unit"), GyroUnit::kRadPerS);
  EXPECT_EQ(parse_accel_unit("m/s2", "--accel-unit"), AccelUnit::kMps2);
  EXPECT_THROW(parse_gyro_unit("dps", "--gyro-unit"), InputError);
  EXPECT_THROW(parse_accel_unit("mg", "--accel-unit"), InputError);
  EXPECT_DOUBLE_EQ(to_si(GyroUnit::kDegPerS), kDegToRad);
  EXPECT_DOUBLE_EQ(to_si(AccelUnit::kG), kGravityMps2);
}

TEST(ImuSamples, RefusesGzipAndMissingFiles) {
  const auto dir = std::filesystem::temp_directory_path();
  const auto gz = dir / "insmc_imu_samples_test.csv.gz";
  {
    std::ofstream out(gz, std::ios::binary);
    out << "\x1f\x8b\x08" << std::string(20, '\0');
  }
  try {
    read_imu_csv(gz, adis_at(100.0));
    ADD_FAILURE() << "gzip accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("gzip-compressed"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("gzip -dc"), std::string::npos) << e.what();
  }
  std::filesystem::remove(gz);
  EXPECT_THROW(read_imu_csv(dir / "insmc_no_such_file.csv", adis_at(100.0)), InputError);
}

}  // namespace
}  // namespace insmc
