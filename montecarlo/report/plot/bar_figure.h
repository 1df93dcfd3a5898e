#pragma once
/// A figure of bar panels as a gnuplot script: per panel the same series
/// (e.g. systems 1 and 2) as clustered bars over that panel's categories
/// (e.g. its largest error sources). Rendered like panel_figure.h.
#include <string>
#include <vector>

#include "montecarlo/report/plot/gnuplot.h"

namespace insmc::mc {

struct BarPanel {
  std::string title;
  std::vector<std::string> categories;
  std::vector<std::vector<double>> values;  ///< [series][category]
};

struct BarFigure {
  std::string stem, title, y_label;
  std::vector<std::string> series;  ///< legend entries, one colour each
  std::vector<BarPanel> panels;
  int columns = 2;
  std::string empty_note = "nothing to draw";  ///< shown in a panel without categories
};

RenderedFigure render_bar_figure(const BarFigure& figure);

}  // namespace insmc::mc
