#include "montecarlo/write/plot/panel_figure.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "montecarlo/write/plot/gnuplot.h"

namespace insmc::mc {
namespace {

// Colour-blind-safe palette (Okabe and Ito).
constexpr const char* kPalette[] = {"#0072B2", "#D55E00", "#009E73", "#CC79A7",
                                    "#E69F00", "#56B4E9", "#000000", "#F0E442"};
constexpr int kPaletteSize = static_cast<int>(std::size(kPalette));

const char* colour(int index) { return kPalette[((index % kPaletteSize) + kPaletteSize) % kPaletteSize]; }

std::string number(double v) { return std::isfinite(v) ? fmt::format("{:.9g}", v) : "NaN"; }

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
        out += fmt::format("{} {} {} {}\n", number(line.x[i]), number(line.y[i]),
                           number(band ? line.lo[i] : line.y[i]), number(band ? line.hi[i] : line.y[i]));
      out += fmt::format("EOD\n{}_marks << EOD\n", block_name(p, l));
      for (const PlotMark& m : line.marks)
        out += fmt::format("{} {} {} {}\n", number(m.x), number(m.y), number(m.lo), number(m.hi));
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
                         number(m));
      out += fmt::format("set label {} at {}, graph 1.0 center offset 0,0.6 font \",9\" textcolor \"#555555\"\n",
                         gnuplot_quote(fmt::format("{:g}", m)), number(m));
    }
    std::string plot = "plot ";
    for (std::size_t l = 0; l < panel.lines.size(); ++l) {
      const PlotLine& line = panel.lines[l];
      const std::string block = block_name(p, l), c = colour(line.colour);
      if (l > 0) plot += ", \\\n     ";
      plot += fmt::format("{0} using 1:3:4 with filledcurves fillcolor \"{1}\" fillstyle transparent solid 0.22 "
                          "noborder notitle, \\\n     "
                          "{0} using 1:2 with lines linecolor \"{1}\" linewidth 2 dashtype {2} title {3}, \\\n     "
                          "{0}_marks using 1:2:3:4 with yerrorbars pointtype 7 pointsize 0.6 linecolor \"{1}\" "
                          "notitle",
                          block, c, line.dashed ? 2 : 1, gnuplot_quote(line.name));
    }
    out += (panel.lines.empty() ? std::string("plot NaN notitle") : plot) + "\n";
  }
  return out + "unset multiplot\n";
}

}  // namespace

std::string panel_figure_script(const PanelFigure& f) {
  const int n = std::max<int>(1, static_cast<int>(f.panels.size()));
  const int columns = std::clamp(f.columns, 1, n), rows = (n + columns - 1) / columns;
  const int width = 560 * columns, height = 90 + 340 * rows;
  std::string out = fmt::format(
      "# {}\n# Written by insmc with its data inline; render again with: gnuplot {}.gp\n"
      "# (writes {}.svg and {}.png in the current folder).\n",
      f.title, f.stem, f.stem, f.stem);
  out += data_blocks(f);
  out += fmt::format("set xlabel {}\nset ylabel {}\n", gnuplot_quote(f.x_label), gnuplot_quote(f.y_label));
  std::size_t most_lines = 0;
  for (const PlotPanel& p : f.panels) most_lines = std::max(most_lines, p.lines.size());
  // Two lines fit in a corner; more go under the axes, one per row.
  out += "set yrange [0:*]\nset grid xtics ytics linecolor \"#dddddd\"\n";
  out += most_lines <= 2 ? "set key top left box opaque font \",9\"\n"
                         : "set key outside below vertical maxrows 4 font \",9\"\n";
  out += "set border linecolor \"#333333\"\nset offsets graph 0, graph 0, graph 0.08, 0\n";
  if (f.log_x) out += "set logscale x\n";
  const std::string body = panels(f, columns, rows);
  out += fmt::format("set terminal svg size {},{} noenhanced font \"sans,11\" background \"white\"\nset output {}\n", width,
                     height, gnuplot_quote(f.stem + ".svg"));
  out += body;
  out += fmt::format("set terminal pngcairo size {},{} noenhanced font \"sans,10\" background \"white\"\nset output {}\n", width,
                     height, gnuplot_quote(f.stem + ".png"));
  out += body + "unset output\n";
  return out;
}

RenderedFigure render_panel_figure(const PanelFigure& f) {
  RenderedFigure r;
  r.script = panel_figure_script(f);
  std::vector<std::string> bytes = render_gnuplot(r.script, {f.stem + ".svg", f.stem + ".png"});
  r.svg = std::move(bytes[0]);
  r.png = std::move(bytes[1]);
  return r;
}

}  // namespace insmc::mc
