// Tests for montecarlo/report/markdown.h.
#include "montecarlo/report/markdown.h"

#include <gtest/gtest.h>

#include <string>

#include "montecarlo/report/csv.h"

namespace insmc::mc {
namespace {

TEST(RenderMarkdown, NumericColumnsRightAlignedTextLeft) {
  Table t({"scheme", "rms_m", "n"});
  t.add_row({"5.1.1", "0.125", "1000"});
  t.add_row({"5.4", "12.5", "200"});
  // "5.1.1" is not a number, so the scheme column stays left-aligned.
  EXPECT_EQ(render_markdown(t),
            "| scheme | rms_m |    n |\n"
            "| ------ | ----: | ---: |\n"
            "| 5.1.1  | 0.125 | 1000 |\n"
            "| 5.4    |  12.5 |  200 |\n");
}

TEST(RenderMarkdown, ValuesWithTheirIntervalAreRightAligned) {
  Table t({"scheme", "rms_m", "note"});
  t.add_row({"none", "28830 ± 480", "a ± b"});
  t.add_row({"5.2", "120 ± 15", "1 ± 2"});
  EXPECT_EQ(render_markdown(t),
            "| scheme |       rms_m | note  |\n"
            "| ------ | ----------: | ----- |\n"
            "| none   | 28830 ± 480 | a ± b |\n"
            "| 5.2    |    120 ± 15 | 1 ± 2 |\n");
}

TEST(RenderMarkdown, EmptyCellsLeaveANumberColumnRightAligned) {
  // envelope.md's accuracy columns: filled on horizontal rows alone.
  Table t({"axis", "cep50_m"});
  t.add_row({"x", ""});
  t.add_row({"horizontal", "8670 ± 260"});
  EXPECT_EQ(render_markdown(t),
            "| axis       |    cep50_m |\n"
            "| ---------- | ---------: |\n"
            "| x          |            |\n"
            "| horizontal | 8670 ± 260 |\n");
}

TEST(RenderMarkdown, HeaderOnlyUsesMinimumDelimiter) {
  const Table t({"a", "bb"});
  EXPECT_EQ(render_markdown(t),
            "| a   | bb  |\n"
            "| --- | --- |\n");
}

TEST(RenderMarkdown, EscapesPipesAndLineBreaks) {
  Table t({"note"});
  t.add_row({"a|b"});
  t.add_row({"x\ny"});
  t.add_row({"p\r\nq"});
  EXPECT_EQ(render_markdown(t),
            "| note   |\n"
            "| ------ |\n"
            "| a\\|b   |\n"
            "| x<br>y |\n"
            "| p<br>q |\n");
}

TEST(RenderMarkdown, PadsByCodePointsNotBytes) {
  Table t({"σ_rad", "x"});  // σ is two bytes in UTF-8
  t.add_row({"1", "nan"});
  EXPECT_EQ(render_markdown(t),
            "| σ_rad |   x |\n"
            "| ----: | --: |\n"
            "|     1 | nan |\n");
}

TEST(RenderMarkdown, MatchesCsvContent) {
  Table t({"k", "v"});
  t.add_row({"alpha", format_number(0.5)});
  const std::string md = render_markdown(t);
  EXPECT_NE(md.find("| alpha |"), std::string::npos);
  EXPECT_NE(md.find("0.5 |"), std::string::npos);
}

}  // namespace
}  // namespace insmc::mc
