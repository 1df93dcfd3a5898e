// Tests for montecarlo/report/interval_format.h.
#include "montecarlo/report/interval_format.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace insmc::mc {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

TEST(IntervalPlace, IsTheSecondFigureOfTheRoundedHalfWidth) {
  EXPECT_EQ(interval_place(480.3), 1);
  EXPECT_EQ(interval_place(48), 0);
  EXPECT_EQ(interval_place(0.0012), -4);
  EXPECT_EQ(interval_place(1000), 2);   // an exact power of ten: "1000" has figures 1, 0
  EXPECT_EQ(interval_place(0.001), -4);
  EXPECT_EQ(interval_place(99.7), 1);   // rounds to 100: the second figure is the tens
  EXPECT_EQ(interval_place(9.96), 0);   // rounds to 10
  EXPECT_EQ(interval_place(0), std::nullopt);
  EXPECT_EQ(interval_place(-3), std::nullopt);
  EXPECT_EQ(interval_place(kNaN), std::nullopt);
  EXPECT_EQ(interval_place(kInf), std::nullopt);
}

TEST(FormatWithInterval, RoundsTheValueToTheIntervalsSecondFigure) {
  EXPECT_EQ(format_with_interval(28825.3, 480.4), "28830 ± 480");
  EXPECT_EQ(format_with_interval(28825.3, 4.8e2), "28830 ± 480");
  EXPECT_EQ(format_with_interval(12251.1, 140), "12250 ± 140");
  EXPECT_EQ(format_with_interval(7401.06, 96.2), "7401 ± 96");
  EXPECT_EQ(format_with_interval(7401.06, 99.7), "7400 ± 100");
  EXPECT_EQ(format_with_interval(3.14159, 0.0213), "3.142 ± 0.021");
  EXPECT_EQ(format_with_interval(-2.5, 0.25), "-2.50 ± 0.25");
  EXPECT_EQ(format_with_interval(12.0, 1.0), "12.0 ± 1.0");  // trailing zeros are figures
}

TEST(FormatWithInterval, TinyAndHugeIntervals) {
  // An interval far below the value: every figure down to its place.
  EXPECT_EQ(format_with_interval(28825.312345, 0.0012), "28825.3123 ± 0.0012");
  // An interval far above the value: the value is not resolved at all.
  EXPECT_EQ(format_with_interval(3.2, 4800), "0 ± 4800");
  // Beyond fixed notation's places: scientific, down to the same place.
  EXPECT_EQ(format_with_interval(2.5e20, 4.8e18), "2.500e+20 ± 4.8e+18");
  EXPECT_EQ(format_with_interval(3.2e-9, 4.8e-11), "3.200e-09 ± 4.8e-11");
  EXPECT_EQ(format_with_interval(1.23456e7, 4.8e6), "12300000 ± 4800000");
  EXPECT_EQ(format_with_interval(1.23456e9, 4.8e8), "1.23e+09 ± 4.8e+08");
  // No more figures than a double holds.
  EXPECT_EQ(format_with_interval(1e12 + 0.5, 1e-9), "1000000000000.500 ± 1.0e-09");
}

TEST(FormatWithInterval, ZeroNaNAndInfinite) {
  EXPECT_EQ(format_with_interval(1234.5678, 0), "1234.57 ± 0");  // every sample alike
  EXPECT_EQ(format_with_interval(0, 0), "0 ± 0");
  // An interval that bounds nothing leaves the value two figures.
  EXPECT_EQ(format_with_interval(1234.5678, kNaN), "1200 ± nan");
  EXPECT_EQ(format_with_interval(1234.5678, kInf), "1200 ± inf");
  EXPECT_EQ(format_with_interval(0.0712, -kInf), "0.071 ± inf");
  EXPECT_EQ(format_with_interval(kNaN, 480), "nan");
  EXPECT_EQ(format_with_interval(kInf, 480), "inf ± 480");
  EXPECT_EQ(format_with_interval(-0.001, 4.8), "0.0 ± 4.8");  // no "-0.0"
}

TEST(FormatSignificant, KeepsTheGivenFigures) {
  EXPECT_EQ(format_significant(12255.3582, 5), "12255");
  EXPECT_EQ(format_significant(8613.609, 5), "8613.6");
  EXPECT_EQ(format_significant(0.000123456, 3), "0.000123");
  EXPECT_EQ(format_significant(99999.7, 5), "100000");
  EXPECT_EQ(format_significant(0, 5), "0");
  EXPECT_EQ(format_significant(kNaN, 5), "nan");
  EXPECT_EQ(format_significant(-kInf, 5), "-inf");
}

}  // namespace
}  // namespace insmc::mc
