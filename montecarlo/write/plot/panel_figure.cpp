#include "montecarlo/write/plot/panel_figure.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "montecarlo/write/plot/gnuplot.h"
#include "montecarlo/write/plot/palette.h"

namespace insmc::mc {
namespace {

std::string block_name(std::size_t panel, std::size_t line) { return fmt::format("$p{}_l{}", panel, line); }

/// Each line's data: x y lo hi, then its marks: x y lo hi.
std::string data_blocks(const PanelFigure& f) {
  std::string out;
  for (std::size_t p = 0; p < f.panels.size(); ++p)
    for (std::size_t l = 0; l < f.panels[p].lines.size(); ++l) {
      const PlotLine& line = f.panels[p].lines[l];
      const bool band = line.lo.size() == line.y.size() && line.hi.size() == line.y.size();
      out += fmt::format("{} << EOD\n", block_name(p, l));
      for (std::size_t i = 0; i < line.x.size() && i < line.y.size(); ++i)
        out += fmt::format("{} {} {} {}\n", plot_number(line.x[i]), plot_number(line.y[i]),
                           plot_number(band ? line.lo[i] : line.y[i]), plot_number(band ? line.hi[i] : line.y[i]));
      out += fmt::format("EOD\n{}_marks << EOD\n", block_name(p, l));
      for (const PlotMark& m : line.marks)
        out += fmt::format("{} {} {} {}\n", plot_number(m.x), plot_number(m.y), plot_number(m.lo), plot_number(m.hi));
      out += "EOD\n";
    }
  return out;
}

/// The multiplot itself, for whichever terminal is set.
std::string panels(const PanelFigure& f, int columns, int rows) {
  std::string out = fmt::format("set multiplot layout {},{} title {} font \",14\"\n", rows, columns,
                                gnuplot_quote(f.title));
  for (std::size_t p = 0; p < f.panels.size(); ++p) {
    const PlotPanel& panel = f.panels[p];
    out += fmt::format("set title {}\n", gnuplot_quote(panel.title));
    out += "unset arrow\nunset label\n";
    for (const double m : f.marked_x) {
      out += fmt::format("set arrow from {0}, graph 0 to {0}, graph 1 nohead dashtype 3 linecolor \"#777777\"\n",
                         plot_number(m));
      out += fmt::format("set label {} at {}, graph 1.0 center offset 0,0.6 font \",9\" textcolor \"#555555\"\n",
                         gnuplot_quote(fmt::format("{:g}", m)), plot_number(m));
    }
    std::string plot = "plot ";
    for (std::size_t l = 0; l < panel.lines.size(); ++l) {
      const PlotLine& line = panel.lines[l];
      const std::string block = block_name(p, l), c = palette_colour(line.colour);
      if (l > 0) plot += ", \\\n     ";
      plot += fmt::format("{0} using 1:3:4 with filledcurves fillcolor \"{1}\" fillstyle transparent solid 0.22 "
                          "noborder notitle, \\\n     "
                          "{0} using 1:2 with lines linecolor \"{1}\" linewidth {4} dashtype {2} title {3}, \\\n     "
                          "{0}_marks using 1:2:3:4 with yerrorbars pointtype 7 pointsize 0.6 linecolor \"{1}\" "
                          "notitle",
                          block, c, line.thin ? 3 : line.dashed ? 2 : 1, gnuplot_quote(line.name), line.thin ? 1 : 2);
    }
    out += panel.lines.empty() ? empty_panel_plot("nothing to draw") : plot + "\n";
  }
  return out + "unset multiplot\n";
}

}  // namespace

std::string panel_figure_script(const PanelFigure& f) {
  const int n = std::max<int>(1, static_cast<int>(f.panels.size()));
  const int columns = std::clamp(f.columns, 1, n), rows = (n + columns - 1) / columns;
  FigureScript script{f.stem, f.title, data_blocks(f), panels(f, columns, rows), std::max(900, 560 * columns),
                      90 + 340 * rows};
  std::string& settings = script.data_and_settings;
  settings += fmt::format("set xlabel {}\nset ylabel {}\n", gnuplot_quote(f.x_label), gnuplot_quote(f.y_label));
  std::size_t most_lines = 0;
  for (const PlotPanel& p : f.panels) most_lines = std::max(most_lines, p.lines.size());
  script.height += rows * 14 * static_cast<int>((most_lines + 1) / 2);  // the keys' rows
  settings += "set grid xtics ytics mytics linecolor \"#dddddd\"\n";
  // Under the axes, where it hides no data: two entries a row.
  settings += "set key outside below horizontal maxcols 2 font \",9\" height 1\n";
  if (f.log_x) settings += "set logscale x\n";
  // A log y axis from the data; a linear one from 0 with room above the top.
  settings += f.log_y ? "set logscale y\nset format y \"%.0e\"\n"
                      : "set yrange [0:*]\nset offsets graph 0, graph 0, graph 0.08, 0\n";
  return figure_script(script);
}

RenderedFigure render_panel_figure(const PanelFigure& f) { return render_figure(f.stem, panel_figure_script(f)); }

}  // namespace insmc::mc
