// Tests for gnuplot_quote and gnuplot_comment (montecarlo/report/plot/gnuplot.h):
// text from the user (file names, titles) must reach gnuplot as text only.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <unistd.h>

#include "montecarlo/report/plot/gnuplot.h"

namespace insmc::mc {
namespace {

namespace fs = std::filesystem;

TEST(GnuplotQuote, EscapesQuotesBackslashesAndBackquotes) {
  EXPECT_EQ(gnuplot_quote(R"(a"b\c`d)"), R"("a\"b\\c\`d")");
  EXPECT_EQ(gnuplot_quote("two\nlines"), R"("two\nlines")");
  EXPECT_EQ(gnuplot_quote(std::string("bell\a\r\x7f!")), R"("bell!")");
}

TEST(GnuplotComment, KeepsOneLine) {
  EXPECT_EQ(gnuplot_comment("title\nset output \"x\""), "title set output \"x\"");
}

// gnuplot runs `command` inside double quotes; the quoted title must not.
TEST(GnuplotQuote, BackquotedCommandInATitleStaysText) {
  if (!gnuplot_available()) GTEST_SKIP() << gnuplot_missing_message();
  const fs::path marker = fs::temp_directory_path() / ("insmc_quote_test_" + std::to_string(::getpid()));
  fs::remove(marker);
  const std::string title = "run `touch " + marker.string() + "` \"done\"";
  const std::string script = "set terminal svg noenhanced\nset output \"q.svg\"\nset title " + gnuplot_quote(title) +
                             "\nplot x\n";
  const std::vector<std::string> drawn = render_gnuplot(script, {"q.svg"});
  ASSERT_EQ(drawn.size(), 1U);
  EXPECT_FALSE(fs::exists(marker)) << "gnuplot ran the backquoted command of the title";
  EXPECT_NE(drawn[0].find("touch"), std::string::npos) << "the title was not drawn as text";
  fs::remove(marker);
}

}  // namespace
}  // namespace insmc::mc
