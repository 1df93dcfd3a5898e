// The gnuplot script of a panel figure (montecarlo/report/plot/panel_figure.h)
// without running gnuplot: a long title broken to fit, a band too narrow to
// see said in the title (and not when it can be seen), a panel's own axis
// labels, its limits and its shaded interval.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "montecarlo/report/plot/panel_figure.h"

namespace insmc::mc {
namespace {

/// One panel, one line from 0 to 10 with a band of ±`half_width` around y = 100.
PanelFigure figure_with_band(double half_width) {
  PanelFigure f;
  f.stem = "test";
  f.title = "A title";
  f.band_name = "95% interval";
  PlotPanel panel;
  panel.title = "panel";
  PlotLine line;
  line.name = "line";
  for (int i = 0; i <= 10; ++i) {
    line.x.push_back(i);
    line.y.push_back(100);
    line.lo.push_back(100 - half_width);
    line.hi.push_back(100 + half_width);
  }
  panel.lines.push_back(line);
  f.panels.push_back(panel);
  return f;
}

/// The multiplot title as the script gives it (the quoted text after "title").
std::string multiplot_title(const std::string& script) {
  const std::size_t at = script.find("set multiplot layout");
  const std::size_t open = script.find('"', at), close = script.find("\" font", open);
  return script.substr(open + 1, close - open - 1);
}

/// The same with its line breaks as spaces.
std::string one_line(std::string title) {
  for (std::size_t at = title.find("\\n"); at != std::string::npos; at = title.find("\\n", at)) title.replace(at, 2, " ");
  return title;
}

TEST(PanelFigure, ABandTooNarrowToSeeIsSaidInTheTitle) {
  // ±0.5 on a panel spanning 0..100.5: under 3 % of it.
  const std::string narrow = one_line(multiplot_title(panel_figure_script(figure_with_band(0.5))));
  EXPECT_NE(narrow.find("the 95% interval is narrower than the lines (at most ±0.5 % of the value)"),
            std::string::npos)
      << narrow;
  // ±10: a fifth of the span, to be seen.
  const std::string wide = multiplot_title(panel_figure_script(figure_with_band(10)));
  EXPECT_EQ(wide.find("narrower"), std::string::npos) << wide;
}

TEST(PanelFigure, ALongTitleIsBrokenIntoLinesThatFitTheCanvas) {
  PanelFigure f = figure_with_band(10);
  const std::string a(60, 'a'), b(60, 'b'), c(60, 'c');
  f.title = a;
  f.title.append(1, ' ').append(b).append(1, ' ').append(c);
  const std::string title = multiplot_title(panel_figure_script(f));
  // 900 px wide: at most 81 characters a line, broken at the spaces.
  std::string expected = a;
  expected.append("\\n").append(b).append("\\n").append(c);
  EXPECT_EQ(title, expected);
}

TEST(PanelFigure, APanelHasItsOwnLabelsLimitsAndShade) {
  PanelFigure f = figure_with_band(10);
  f.x_label = "figure x";
  f.panels[0].x_label = "panel x [min]";
  PlotPanel::Limit limit;
  limit.y = 150;
  limit.name = "limit 2nmi at 84 min";
  f.panels[0].limits.push_back(limit);
  f.panels[0].shade_x0 = 0;
  f.panels[0].shade_x1 = 2;
  const std::string script = panel_figure_script(f);
  EXPECT_NE(script.find("set xlabel \"panel x [min]\""), std::string::npos);
  EXPECT_EQ(script.find("set xlabel \"figure x\""), std::string::npos) << "the panel's own label wins";
  EXPECT_NE(script.find("150 with lines dashtype 2 linewidth 2 linecolor \"#CC0000\" title \"limit 2nmi at 84 min\""),
            std::string::npos);
  EXPECT_NE(script.find("set object 1 rect from 0, graph 0 to 2, graph 1 behind"), std::string::npos);
  // A limit at one time: a marker there, its point in a data block of its own.
  PlotPanel::Limit at_42;
  at_42.y = 120;
  at_42.name = "limit 1nmi at 42 min";
  at_42.x = 42;
  f.panels[0].limits = {at_42};
  const std::string marked = panel_figure_script(f);
  EXPECT_NE(marked.find("$p0_l0_limit0 << EOD\n42 120\nEOD\n"), std::string::npos) << marked;
  EXPECT_NE(marked.find("$p0_l0_limit0 using 1:2 with points"), std::string::npos);
  EXPECT_EQ(marked.find("120 with lines"), std::string::npos) << "not a level across the panel";
}

TEST(PanelFigure, AWordLongerThanALineIsBrokenInside) {
  PanelFigure f = figure_with_band(10);
  f.title = std::string(200, 'p');
  const std::string title = multiplot_title(panel_figure_script(f));
  // 900 px wide: 81 characters a line.
  std::string expected = std::string(81, 'p');
  expected.append("\\n").append(std::string(81, 'p')).append("\\n").append(std::string(38, 'p'));
  EXPECT_EQ(title, expected);
}

}  // namespace
}  // namespace insmc::mc
