// insmc noise's report (montecarlo/records/noise/noise_report.h): its set
// and formats, and the fitted terms as the tables give them, in the units
// engineers quote, against a recording whose noise is known.
#include "montecarlo/records/noise/noise_report.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "lib/noise/noise_analysis.h"
#include "lib/noise/recording.h"
#include "lib/units/units.h"
#include "tests/cli/csv_rows.h"

namespace insmc::noise {
namespace {

constexpr double kDt = 0.1;                       // 10 Hz
constexpr double kArwDegRtH = 0.3;                // gyro white noise [deg/√h]
constexpr double kVrwMpsRtH = 0.05;               // accelerometer white noise [m/s/√h]
/// Of each interval: the six channels' intervals all hold the truth with
/// probability at least 1 − 6 (1 − c) = 0.99 (Bonferroni).
constexpr double kConfidence = 1.0 - 0.01 / 6;

/// 30 min of white noise on every channel, the platform at rest (z down).
SensorRecording white_recording() {
  ImuSamples s;
  s.source = "white.csv";
  std::mt19937_64 rng(11);
  std::normal_distribution<double> e(0.0, 1.0);
  const double gyro_sd = kArwDegRtH * kDegToRad / std::sqrt(kHourToS) / std::sqrt(kDt);
  const double accel_sd = kVrwMpsRtH / std::sqrt(kHourToS) / std::sqrt(kDt);
  for (int k = 0; k < 18000; ++k) {
    s.t_s.push_back(k * kDt);
    const double g0 = e(rng), g1 = e(rng), g2 = e(rng), a0 = e(rng), a1 = e(rng), a2 = e(rng);
    s.gyro_b_radps.push_back(Vec3(gyro_sd * g0, gyro_sd * g1, gyro_sd * g2));
    s.accel_b_mps2.push_back(Vec3(accel_sd * a0, accel_sd * a1, -9.80665 + accel_sd * a2));
  }
  const std::vector<ImuSamples> one{s};
  return make_recording(one);
}

using testing::csv_rows;

class NoiseReport : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    rec_ = new SensorRecording(white_recording());
    NoiseOptions options;
    options.confidence = kConfidence;
    analysis_ = new NoiseAnalysis(analyse_noise(*rec_, options));
  }
  static void TearDownTestSuite() {
    delete analysis_;
    delete rec_;
  }
  static SensorRecording* rec_;
  static NoiseAnalysis* analysis_;
};
SensorRecording* NoiseReport::rec_ = nullptr;
NoiseAnalysis* NoiseReport::analysis_ = nullptr;

TEST_F(NoiseReport, HoldsItsLayoutsFilesAndShowsMarkdownOrJson) {
  const mc::Report r = noise_report(*rec_, *analysis_, kConfidence);
  const mc::ReportOutline& outline = r.outline();
  EXPECT_EQ(outline.command, "noise");
  EXPECT_TRUE(outline.offers(mc::ReportFormat::kMarkdown) && outline.offers(mc::ReportFormat::kJson));
  EXPECT_FALSE(outline.offers(mc::ReportFormat::kCsv));
  for (const std::string& name : outline.files) EXPECT_FALSE(r.file_text(name).empty()) << name;
  EXPECT_EQ(r.shown(mc::ReportFormat::kMarkdown), r.file_text("noise.md"));
  EXPECT_EQ(r.shown(mc::ReportFormat::kJson), r.file_text("noise.json"));
  const nlohmann::json j = nlohmann::json::parse(r.file_text("noise.json"));
  EXPECT_EQ(j.at("channels").size(), kChannels);
}

TEST_F(NoiseReport, AllanTableHoldsEveryChannelsEveryClusterTime) {
  const auto rows = csv_rows(noise_report(*rec_, *analysis_, kConfidence).file_text("allan.csv"));
  std::size_t expected = 0;
  for (const ChannelNoise& ch : analysis_->channels) expected += ch.allan.size();
  ASSERT_EQ(rows.size(), expected + 1);
  EXPECT_EQ(rows.front().front(), "channel");
  for (std::size_t i = 1; i < rows.size(); ++i) {
    const double adev = std::stod(rows[i][2]), lower = std::stod(rows[i][3]), upper = std::stod(rows[i][4]);
    EXPECT_LE(lower, adev);
    EXPECT_LE(adev, upper);
  }
}

/// The white-noise term of each channel in the units engineers quote
/// (deg/√h, m/s/√h): the known value inside the interval the table gives,
/// and the quoted value the SI value converted.
TEST_F(NoiseReport, WhiteNoiseIsQuotedInItsSpecUnitsWithTheTruthInside) {
  const auto rows = csv_rows(noise_report(*rec_, *analysis_, kConfidence).file_text("noise_terms.csv"));
  std::map<std::string, std::vector<std::string>> white;
  for (const auto& row : rows)
    if (row.size() == 10 && (row[1] == term_name(NoiseTerm::kWhiteRate, SensorKind::kGyro) ||
                             row[1] == term_name(NoiseTerm::kWhiteRate, SensorKind::kAccelerometer)))
      white[row[0]] = row;
  ASSERT_EQ(white.size(), kChannels) << "every channel's white noise is selected";
  for (const auto& [channel, row] : white) {
    const bool gyro = channel.rfind("gyro", 0) == 0;
    const double truth = gyro ? kArwDegRtH : kVrwMpsRtH;
    EXPECT_EQ(row[9], gyro ? "deg/sqrt(h)" : "m/s/sqrt(h)") << channel;
    const double value_si = std::stod(row[2]), value_spec = std::stod(row[6]);
    const double per_si = gyro ? std::sqrt(kHourToS) / kDegToRad : std::sqrt(kHourToS);
    EXPECT_NEAR(value_spec, value_si * per_si, 1e-9 * value_spec) << channel;
    EXPECT_LE(std::stod(row[7]), truth) << channel;
    EXPECT_GE(std::stod(row[8]), truth) << channel;
  }
}

}  // namespace
}  // namespace insmc::noise
