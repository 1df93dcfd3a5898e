// check's bounds file: every mistake with FILE:LINE:COLUMN, the caps.
#include "montecarlo/study/check/bounds_file.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <string>

#include "lib/common/input_error.h"
#include "lib/units/units.h"
#include "tests/unit/input_error_of.h"

namespace insmc::mc {
namespace {

std::string error_of(const std::string& text) {
  return test::input_error_of([&] { parse_bounds_text(text, "bounds.txt"); });
}

TEST(BoundsFile, ReadsBounds) {
  const auto b = parse_bounds_text(
      "\xEF\xBB\xBF# CI bounds\n\nscheme=none system=2 axis=horizontal t_min=84 rms_m<=9000\n"
      "  scheme=5.2 system=1 axis=x t_min=42 rms_ft<=100 confidence=0.99  # tight\n",
      "bounds.txt");
  ASSERT_EQ(b.size(), 2u);
  EXPECT_EQ(b[0].line, 3);
  EXPECT_EQ(b[0].scheme, Scheme::kNone);
  EXPECT_EQ(b[0].system, System::kGyrocompass);
  EXPECT_EQ(b[0].axis, Axis::kHorizontal);
  EXPECT_EQ(b[0].t_s, 84 * 60.0);
  EXPECT_EQ(b[0].limit_m, 9000.0);
  EXPECT_FALSE(b[0].confidence);
  EXPECT_EQ(b[1].scheme, Scheme::k5_2);
  EXPECT_EQ(b[1].limit_m, 100 * kFtToM);
  EXPECT_EQ(b[1].confidence, 0.99);
}

TEST(BoundsFile, OtherLimitFormsAreRefusedNotIgnored) {
  const std::string base = "scheme=none system=2 axis=horizontal t_min=84 ";
  EXPECT_NE(error_of(base + "rms_m>=5")
                .find("bounds.txt:1:47: limit 'rms_m>=5': expected METRIC_UNIT<=NUMBER or METRIC<=NUMBERUNIT"),
            std::string::npos)
      << error_of(base + "rms_m>=5");
  EXPECT_NE(error_of(base + "rms_km<=5").find("bounds.txt:1:47: limit 'rms_km<=5'"), std::string::npos);
  EXPECT_NE(error_of(base + "rms_m=5").find("limit 'rms_m=5'"), std::string::npos);
  EXPECT_NE(error_of(base + "rms_m<=5 rms_ft<=3").find("bounds.txt:1:56: a second limit 'rms_ft<=3' (the first at column 47)"),
            std::string::npos)
      << error_of(base + "rms_m<=5 rms_ft<=3");
  EXPECT_NE(error_of(base + "rms_m<=abc").find("bounds.txt:1:54: rms_m = 'abc': not a number"), std::string::npos)
      << error_of(base + "rms_m<=abc");
  EXPECT_NE(error_of(base + "rms_m<=-1").find("the limit must lie in [0, 40000 km]"), std::string::npos);
  EXPECT_NE(error_of(base + "rms_nmi<=1e306").find("the limit must lie in [0, 40000 km]"), std::string::npos)
      << "a limit that overflows to inf m would always hold";
}

TEST(BoundsFile, ReadsPercentileLimitsAndNauticalMiles) {
  const std::string h = "scheme=none system=2 axis=horizontal t_min=84 ";
  const auto b = parse_bounds_text(h + "cep50_m<=3000\n" + h + "p95_nmi<=2\n" + h + "cep50<=3nmi\n" + h +
                                       "rms<=500ft\n" + h + "cep95_ft<=100\n" + h + "rms_nmi<=1.5\n",
                                   "bounds.txt");
  ASSERT_EQ(b.size(), 6u);
  EXPECT_EQ(b[0].metric, BoundMetric::kCep50);
  EXPECT_EQ(b[0].limit_m, 3000.0);
  EXPECT_EQ(b[1].metric, BoundMetric::kCep95);
  EXPECT_EQ(b[1].limit_m, 2 * kNmiToM);
  EXPECT_EQ(b[2].metric, BoundMetric::kCep50);
  EXPECT_EQ(b[2].limit_m, 3 * kNmiToM);
  EXPECT_EQ(b[3].metric, BoundMetric::kRms);
  EXPECT_EQ(b[3].limit_m, 500 * kFtToM);
  EXPECT_EQ(b[4].metric, BoundMetric::kCep95);
  EXPECT_EQ(b[4].limit_m, 100 * kFtToM);
  EXPECT_EQ(b[5].metric, BoundMetric::kRms);
  EXPECT_EQ(b[5].limit_m, 1.5 * kNmiToM);
}

TEST(BoundsFile, PercentileLimitsNeedTheHorizontalAxis) {
  const std::string e = error_of("scheme=none system=2 axis=x t_min=84 cep50_m<=5");
  EXPECT_NE(e.find("bounds.txt:1:38: limit 'cep50_m<=5': cep50 is a percentile of the horizontal radial error; it "
                   "needs axis=horizontal, not axis=x"),
            std::string::npos)
      << e;
}

TEST(BoundsFile, ALimitsUnitIsCheckedWhereverItIsWritten) {
  const std::string base = "scheme=none system=2 axis=horizontal t_min=84 ";
  EXPECT_NE(error_of(base + "cep50<=3").find("bounds.txt:1:54: cep50 = 3: a unit is required"), std::string::npos)
      << error_of(base + "cep50<=3");
  EXPECT_NE(error_of(base + "p95<=3parsec").find("bounds.txt:1:52: p95 = 3parsec: unknown unit 'parsec'"),
            std::string::npos)
      << error_of(base + "p95<=3parsec");
  EXPECT_NE(error_of(base + "cep50_m<=3nmi").find("bounds.txt:1:56: cep50_m = '3nmi'"), std::string::npos)
      << error_of(base + "cep50_m<=3nmi");
  EXPECT_NE(error_of(base + "cep50_furlong<=3").find("bounds.txt:1:47: limit 'cep50_furlong<=3': expected"),
            std::string::npos)
      << error_of(base + "cep50_furlong<=3");
  EXPECT_NE(error_of(base + "p95<=-1m").find("bounds.txt:1:52: 'p95<=-1m': the limit must lie in [0, 40000 km]"), std::string::npos)
      << error_of(base + "p95<=-1m");
}

TEST(BoundsFile, DuplicateKeysOnALineAreRefused) {
  const std::string e = error_of("scheme=none system=2 axis=x t_min=84 scheme=5.2 rms_m<=5");
  EXPECT_NE(e.find("bounds.txt:1:38: scheme given twice on one line (first at column 1)"), std::string::npos) << e;
}

TEST(BoundsFile, MessagesGiveLineAndColumn) {
  EXPECT_NE(error_of("\nscheme=none system=3 axis=x t_min=84 rms_m<=5").find("bounds.txt:2:20: system = '3': must be 1"),
            std::string::npos)
      << error_of("\nscheme=none system=3 axis=x t_min=84 rms_m<=5");
  EXPECT_NE(error_of("scheme=none system=1 axis=sideways t_min=84 rms_m<=5").find("bounds.txt:1:27: axis = 'sideways'"),
            std::string::npos);
  EXPECT_NE(error_of("scheme=none system=1 axis=x t_min=400 rms_m<=5").find("bounds.txt:1:35: t_min = '400': must be"),
            std::string::npos);
  EXPECT_NE(error_of("scheme=none system=1 axis=x t_min=4 rms_m<=5 colour=red").find("bounds.txt:1:46: unknown key 'colour'"),
            std::string::npos);
  EXPECT_NE(error_of("scheme=none system=1 axis=x rms_m<=5").find("bounds.txt:1:1: missing t_min"), std::string::npos);
  EXPECT_NE(error_of("# nothing\n").find("bounds.txt: holds no bound"), std::string::npos);
}

TEST(BoundsFile, EchoesAreEscapedAndCut) {
  const std::string e = error_of("scheme=\x1b[2J" + std::string(300, 'n') + " system=1 axis=x t_min=4 rms_m<=5");
  EXPECT_EQ(e.find('\x1b'), std::string::npos) << e;
  EXPECT_NE(e.find("scheme = '\\x1B[2J"), std::string::npos) << e;
  EXPECT_NE(e.find("\u2026(304 bytes)'"), std::string::npos) << e;
}

TEST(BoundsFile, CapsOnReportTimesBoundsAndLines) {
  std::string text;
  for (std::size_t i = 0; i <= kMaxBoundsReportTimes; ++i)
    text += fmt::format("scheme=none system=1 axis=x t_min={} rms_m<=5\n", i);
  EXPECT_NE(error_of(text).find(fmt::format("bounds.txt:{}:35: more than {} distinct t_min values", kMaxBoundsReportTimes + 1,
                                            kMaxBoundsReportTimes)),
            std::string::npos)
      << error_of(text);
  std::string many;
  for (std::size_t i = 0; i <= kMaxBounds; ++i) many += "scheme=none system=1 axis=x t_min=4 rms_m<=5\n";
  EXPECT_NE(error_of(many).find(fmt::format("bounds.txt:{}:1: more than {} bounds", kMaxBounds + 1, kMaxBounds)),
            std::string::npos);
  EXPECT_NE(error_of(std::string(kMaxBoundsLineBytes + 1, ' ')).find("bounds.txt:1:1025: line of 1025 bytes"),
            std::string::npos);
}

}  // namespace
}  // namespace insmc::mc
