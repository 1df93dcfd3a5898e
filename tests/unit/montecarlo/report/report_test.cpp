// A command's report (montecarlo/report/report.h): the names a outline
// declares before the work are the only ones its report may hold, figures
// are drawn only when the set is, and each format shows what was given for it.
#include "montecarlo/report/report.h"

#include <gtest/gtest.h>

#include <optional>
#include <string>
#include <vector>

namespace insmc::mc {
namespace {

ReportOutline two_formats() {
  return {"demo", {"demo.md", "demo.json"}, {"fig"}, {ReportFormat::kMarkdown, ReportFormat::kJson}};
}

TEST(ReportOutline, SetNamesAreTheFilesThenEachFiguresThree) {
  EXPECT_EQ(two_formats().set_names(),
            (std::vector<std::string>{"demo.md", "demo.json", "fig.gp", "fig.svg", "fig.png"}));
}

TEST(ReportOutline, OffersOnlyTheFormatsItNamesAndSaysSo) {
  const ReportOutline two = two_formats();
  EXPECT_TRUE(two.offers(ReportFormat::kJson));
  EXPECT_FALSE(two.offers(ReportFormat::kCsv));
  EXPECT_EQ(two.offered_text(), "markdown or json");
  EXPECT_EQ((ReportOutline{"all", {}, {}}.offered_text()), "markdown, csv or json");
  EXPECT_EQ((ReportOutline{"one", {}, {}, {ReportFormat::kCsv}}.offered_text()), "csv");
}

TEST(Report, FiguresAreDrawnOnlyWhenTheSetIsAndEachTimeItIs) {
  int drawn = 0;
  Report report(two_formats());
  report.file("demo.md", "# md\n")
      .file("demo.json", "{}\n")
      .figure("fig", [&drawn] {
        ++drawn;
        return RenderedFigure{"script", "<svg/>", "png"};
      })
      .shown(ReportFormat::kMarkdown, "# md\n")
      .shown(ReportFormat::kJson, "{}\n");
  EXPECT_EQ(report.shown(ReportFormat::kJson), "{}\n");
  EXPECT_EQ(report.file_text("demo.md"), "# md\n");
  EXPECT_EQ(drawn, 0);
  const OutputSetFiles set = report.draw_set();
  EXPECT_EQ(drawn, 1);
  std::vector<std::string> names;
  for (const auto& [name, contents] : set) names.push_back(name);
  EXPECT_EQ(names, two_formats().set_names());
  EXPECT_EQ(set.back().second, "png");
}

TEST(ReportDeathTest, ANameOrFormatTheLayoutDoesNotHoldIsAnInternalError) {
  Report report(two_formats());
  EXPECT_DEATH(report.file("other.csv", ""), "demo writes other.csv, which its outline does not name");
  EXPECT_DEATH(report.figure("other", [] { return RenderedFigure{}; }), "demo draws other");
  EXPECT_DEATH(report.shown(ReportFormat::kCsv, ""), "demo shows csv, which its outline does not offer");
  EXPECT_DEATH((void)report.shown(ReportFormat::kJson), "demo shows nothing in json");
  report.file("demo.md", "");
  EXPECT_DEATH(report.file("demo.md", ""), "demo writes demo.md twice");
}

TEST(FullTablesLine, NamesThePathsInTheFolderOrHowToGetThem) {
  EXPECT_EQ(full_tables_line("run", {"envelope.md", "envelope.csv"}, std::string("out/")),
            "Full tables (every axis and time): out/envelope.md, out/envelope.csv\n");
  EXPECT_EQ(full_tables_line("run", {"envelope.md", "envelope.csv"}, std::nullopt),
            "Full tables (every axis and time): insmc run --full, or --out DIR for envelope.md and envelope.csv, or "
            "--format csv\n");
  EXPECT_EQ(full_tables_line("rank", {"rank.md", "ranking.csv", "breakeven.csv"}, std::nullopt),
            "Full tables (every axis and time): insmc rank --full, or --out DIR for rank.md, ranking.csv and "
            "breakeven.csv, or --format csv\n");
}

}  // namespace
}  // namespace insmc::mc
