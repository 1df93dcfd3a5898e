#pragma once
/// A figure of line panels (small multiples) as a gnuplot script: each panel
/// its own axes, each line with its shaded confidence band and its marks
/// (points with error bars), and marked x values (the report times
/// 42/63/84 min) as labelled dotted verticals. The script holds its data inline and writes
/// `<stem>.svg` and `<stem>.png` in the folder it runs in (plot/gnuplot.h).
#include <limits>
#include <string>
#include <vector>

#include "montecarlo/report/plot/gnuplot.h"

namespace insmc::mc {

/// A point drawn with its interval (the report times' RMS).
struct PlotMark {
  double x, y, lo, hi;
};

struct PlotLine {
  std::string name;            ///< legend entry
  std::vector<double> x, y;
  std::vector<double> lo, hi;  ///< the band (same length as y), or empty
  std::vector<PlotMark> marks;
  int colour = 0;              ///< palette index (panel_figure.cpp)
  bool dashed = false;
  bool thin = false;           ///< a reference (e.g. the covariance prediction): 1 px, dotted
};

struct PlotPanel {
  std::string title;
  std::vector<PlotLine> lines;
  /// This panel's axis labels, when they differ from the figure's (empty:
  /// the figure's).
  std::string x_label, y_label;
  /// An x interval shaded behind the lines (e.g. a part of a recording the
  /// analysis leaves out); none when shade_x1 <= shade_x0.
  double shade_x0 = 0, shade_x1 = 0;
  /// Limits, each with its legend entry: at a time (x finite), a red
  /// marker there; otherwise a red dashed level across the panel.
  struct Limit {
    double y;
    std::string name;
    double x = std::numeric_limits<double>::quiet_NaN();
  };
  std::vector<Limit> limits;
};

struct PanelFigure {
  std::string stem;                ///< output names: stem.svg, stem.png
  std::string title;               ///< over all panels
  std::string x_label, y_label;    ///< every panel's axes
  std::vector<PlotPanel> panels;
  std::vector<double> marked_x;    ///< dotted verticals, labelled with their value
  bool log_x = false;
  bool log_y = false;              ///< else linear, from 0 unless signed_y
  bool signed_y = false;           ///< a linear y axis around the data (values of either sign)
  /// What the shaded bands are (e.g. "95 % interval"): when every band is
  /// narrower than the lines can show, the title says so and how narrow.
  std::string band_name;
  int columns = 2;                 ///< panels per row (fewer when there are fewer panels)
};

/// The gnuplot script of `figure` (gnuplot 5.4).
std::string panel_figure_script(const PanelFigure& figure);

/// The script rendered by gnuplot.
RenderedFigure render_panel_figure(const PanelFigure& figure);

}  // namespace insmc::mc
