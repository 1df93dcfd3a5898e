// Tests for montecarlo/report/csv.h.
#include "montecarlo/report/csv.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>
#include <string>

namespace insmc::mc {
namespace {

TEST(FormatNumber, TableOfCases) {
  struct Case {
    double x;
    const char* expected;
  };
  constexpr double kInf = std::numeric_limits<double>::infinity();
  const std::array<Case, 16> cases{{
      {42.0, "42"},
      {-7.0, "-7"},
      {0.0, "0"},
      {-0.0, "0"},
      {1e6, "1000000"},
      {123456789012345.0, "123456789012345"},  // integral, exact below 1e15
      {1e15, "1e+15"},
      {0.5, "0.5"},
      {1.0 / 3.0, "0.333333333"},
      {-2.0 / 3.0, "-0.666666667"},
      {1.5e-7, "1.5e-07"},
      {123456.789, "123456.789"},
      {1234567.891, "1234567.89"},
      {kInf, "inf"},
      {-kInf, "-inf"},
      {std::numeric_limits<double>::quiet_NaN(), "nan"},
  }};
  for (const Case& c : cases) EXPECT_EQ(format_number(c.x), c.expected) << "x = " << c.x;
}

TEST(FormatNumber, NineSignificantDigitsRoundTripThroughParsing) {
  for (const double x : {0.1, 2.718281828459045, 6.02214076e23, 1.602176634e-19}) {
    const double back = std::stod(format_number(x));
    EXPECT_NEAR(back, x, 5e-9 * std::fabs(x)) << format_number(x);
  }
}

TEST(RenderCsv, HeaderAndRows) {
  Table t({"time_s", "rms_m", "n"});
  t.add_row({format_number(600), format_number(0.125), format_number(1000)});
  t.add_row({"1200", "0.25", "1000"});
  EXPECT_EQ(render_csv(t), "time_s,rms_m,n\n600,0.125,1000\n1200,0.25,1000\n");
}

TEST(RenderCsv, HeaderOnly) {
  const Table t({"a"});
  EXPECT_EQ(render_csv(t), "a\n");
}

TEST(RenderCsv, QuotesSpecialCellsPerRfc4180) {
  Table t({"name", "note"});
  t.add_row({"a,b", "say \"hi\""});
  t.add_row({"line\nbreak", " padded "});
  t.add_row({"", "plain"});
  EXPECT_EQ(render_csv(t),
            "name,note\n"
            "\"a,b\",\"say \"\"hi\"\"\"\n"
            "\"line\nbreak\",\" padded \"\n"
            ",plain\n");
}

TEST(TableDeathTest, RowWidthMustMatchHeader) {
  Table t({"a", "b"});
  EXPECT_DEATH(t.add_row({"1"}), "1 cells for 2 columns");
}

}  // namespace
}  // namespace insmc::mc
