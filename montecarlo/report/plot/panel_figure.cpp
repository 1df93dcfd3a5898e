#include "montecarlo/report/plot/panel_figure.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "montecarlo/report/plot/gnuplot.h"
#include "montecarlo/report/plot/palette.h"

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
  for (std::size_t p = 0; p < f.panels.size(); ++p)
    for (std::size_t i = 0; i < f.panels[p].limits.size(); ++i)
      if (std::isfinite(f.panels[p].limits[i].x))
        out += fmt::format("{}_limit{} << EOD\n{} {}\nEOD\n", block_name(p, 0), i, plot_number(f.panels[p].limits[i].x),
                           plot_number(f.panels[p].limits[i].y));
  return out;
}

/// When every band of the figure is too narrow to see (under 3 % of its
/// panel's y span, about 10 px), the sentence that says so and how narrow
/// they are; empty otherwise.
std::string invisible_band_note(const PanelFigure& f) {
  if (f.band_name.empty() || f.log_y) return "";
  double widest_share = 0, widest_relative = 0;
  bool any = false;
  for (const PlotPanel& panel : f.panels) {
    double top = 0, bottom = 0, widest = 0;
    for (const PlotLine& line : panel.lines) {
      const bool band = line.lo.size() == line.y.size() && line.hi.size() == line.y.size();
      for (std::size_t i = 0; i < line.y.size(); ++i) {
        if (!std::isfinite(line.y[i])) continue;
        top = std::max(top, band ? std::max(line.hi[i], line.y[i]) : line.y[i]);
        bottom = std::min(bottom, band ? std::min(line.lo[i], line.y[i]) : line.y[i]);
        if (!band || !std::isfinite(line.hi[i] - line.lo[i])) continue;
        any = true;
        widest = std::max(widest, line.hi[i] - line.lo[i]);
        if (std::abs(line.y[i]) > 0)
          widest_relative = std::max(widest_relative, 0.5 * (line.hi[i] - line.lo[i]) / std::abs(line.y[i]));
      }
    }
    if (top > bottom) widest_share = std::max(widest_share, widest / (top - bottom));
  }
  if (!any || widest_share >= 0.03) return "";
  return fmt::format("the {} is narrower than the lines (at most ±{:.2g} % of the value)", f.band_name,
                     100 * widest_relative);
}

/// `text` broken at spaces into lines of at most `width` characters (a
/// longer word, e.g. a file's path, broken inside it).
std::string wrapped(const std::string& text, std::size_t width) {
  std::string out, line;
  std::size_t at = 0;
  while (at < text.size()) {
    const std::size_t end = std::min({text.find(' ', at), text.size(), at + width});
    const std::string word = text.substr(at, end - at);
    if (!line.empty() && line.size() + 1 + word.size() > width) {
      out += line + "\n";
      line.clear();
    }
    line += (line.empty() ? "" : " ") + word;
    at = end < text.size() && text[end] == ' ' ? end + 1 : end;
  }
  return out + line;
}

/// The multiplot itself, for whichever terminal is set.
std::string panels(const PanelFigure& f, const std::string& title, int columns, int rows) {
  std::string out = fmt::format("set multiplot layout {},{} title {} font \",14\"\n", rows, columns,
                                gnuplot_quote(title));
  for (std::size_t p = 0; p < f.panels.size(); ++p) {
    const PlotPanel& panel = f.panels[p];
    out += fmt::format("set title {}\n", gnuplot_quote(panel.title));
    out += fmt::format("set xlabel {}\nset ylabel {}\n", gnuplot_quote(panel.x_label.empty() ? f.x_label : panel.x_label),
                       gnuplot_quote(panel.y_label.empty() ? f.y_label : panel.y_label));
    out += "unset arrow\nunset label\nunset object 1\n";
    if (panel.shade_x1 > panel.shade_x0)
      out += fmt::format("set object 1 rect from {}, graph 0 to {}, graph 1 behind fillcolor \"#e8e8e8\" "
                         "fillstyle solid 1.0 noborder\n",
                         plot_number(panel.shade_x0), plot_number(panel.shade_x1));
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
      plot += fmt::format("{0} using 1:3:4 with filledcurves fillcolor \"{1}\" fillstyle transparent solid 0.3 "
                          "noborder notitle, \\\n     "
                          "{0} using 1:2 with lines linecolor \"{1}\" linewidth {4} dashtype {2} title {3}, \\\n     "
                          "{0}_marks using 1:2:3:4 with yerrorbars pointtype 7 pointsize 0.6 linecolor \"{1}\" "
                          "notitle",
                          block, c, line.thin ? 3 : line.dashed ? 2 : 1, gnuplot_quote(line.name), line.thin ? 1 : 2);
    }
    for (std::size_t i = 0; i < panel.limits.size() && !panel.lines.empty(); ++i) {
      const PlotPanel::Limit& limit = panel.limits[i];
      if (std::isfinite(limit.x))  // a limit at one time: a marker (a bar with a downward triangle) there
        plot += fmt::format(", \\\n     {}_limit{} using 1:2 with points pointtype {} pointsize 2.2 linewidth 2 "
                            "linecolor \"#CC0000\" title {}",
                            block_name(p, 0), i, 11 - 2 * static_cast<int>(i % 2), gnuplot_quote(limit.name));
      else
        plot += fmt::format(", \\\n     {} with lines dashtype {} linewidth 2 linecolor \"#CC0000\" title {}",
                            plot_number(limit.y), 2 + i % 3, gnuplot_quote(limit.name));
    }
    out += panel.lines.empty() ? empty_panel_plot("nothing to draw") : plot + "\n";
  }
  return out + "unset multiplot\n";
}

}  // namespace

std::string panel_figure_script(const PanelFigure& f) {
  const int n = std::max<int>(1, static_cast<int>(f.panels.size()));
  const int columns = std::clamp(f.columns, 1, n), rows = (n + columns - 1) / columns;
  const int width = std::max(900, 560 * columns);
  // The title in lines that fit the canvas (14 pt sans: about 10 px a character, with room).
  const std::string note = invisible_band_note(f);
  const std::string title = wrapped(note.empty() ? f.title : f.title + "; " + note, static_cast<std::size_t>(width / 11));
  const int title_lines = 1 + static_cast<int>(std::count(title.begin(), title.end(), '\n'));
  FigureScript script{f.stem, f.title, data_blocks(f), panels(f, title, columns, rows), width,
                      90 + 340 * rows + 22 * (title_lines - 1)};
  std::string& settings = script.data_and_settings;
  std::size_t most_lines = 0;
  for (const PlotPanel& p : f.panels) most_lines = std::max(most_lines, p.lines.size() + p.limits.size());
  script.height += rows * 14 * static_cast<int>((most_lines + 1) / 2);  // the keys' rows
  settings += "set grid xtics ytics mytics linecolor \"#dddddd\"\n";
  // Under the axes, where it hides no data: two entries a row.
  settings += "set key outside below horizontal maxcols 2 font \",9\" height 1\n";
  // A log x axis ends where the data end (it would run on to the next
  // decade); a linear one keeps gnuplot's round ends (room for the marks).
  if (f.log_x) settings += "set logscale x\nset autoscale xfix\n";
  // A log y axis from the data; a linear one from 0 with room above the top.
  settings += f.log_y      ? "set logscale y\nset format y \"%.0e\"\n"
              : f.signed_y ? "set offsets graph 0, graph 0, graph 0.08, graph 0.08\n"
                           : "set yrange [0:*]\nset offsets graph 0, graph 0, graph 0.08, 0\n";
  return figure_script(script);
}

RenderedFigure render_panel_figure(const PanelFigure& f) { return render_figure(f.stem, panel_figure_script(f)); }

}  // namespace insmc::mc
