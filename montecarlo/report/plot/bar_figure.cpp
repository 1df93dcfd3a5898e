#include "montecarlo/report/plot/bar_figure.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "montecarlo/report/plot/palette.h"

namespace insmc::mc {

namespace {

std::string bar_figure_script(const BarFigure& f) {
  const int n = std::max<int>(1, static_cast<int>(f.panels.size()));
  const int columns = std::clamp(f.columns, 1, n), rows = (n + columns - 1) / columns;
  const std::size_t series = std::max<std::size_t>(1, f.series.size());
  const double width = 0.8 / static_cast<double>(series);
  FigureScript script{f.stem, f.title, "", "", 560 * columns, 90 + 380 * rows};
  std::string& data = script.data_and_settings;
  for (std::size_t p = 0; p < f.panels.size(); ++p) {
    // One row per category: its name, then one value per series.
    data += fmt::format("$b{} << EOD\n", p);
    const BarPanel& panel = f.panels[p];
    for (std::size_t c = 0; c < panel.categories.size(); ++c) {
      data += gnuplot_quote(panel.categories[c]);
      for (std::size_t s = 0; s < series; ++s)
        data += " " + plot_number(s < panel.values.size() && c < panel.values[s].size() ? panel.values[s][c] : NAN);
      data += "\n";
    }
    data += "EOD\n";
  }
  data += fmt::format("set ylabel {}\nset yrange [0:*]\nset offsets 0.6, 0.6, graph 0.08, 0\n",
                      gnuplot_quote(f.y_label));
  data += "set style fill solid 0.85 noborder\nset grid ytics linecolor \"#dddddd\"\n";
  data += "set xtics rotate by -40 left nomirror font \",9\"\nset key top right box opaque font \",9\"\n";
  std::string& body = script.body;
  body += fmt::format("set multiplot layout {},{} title {} font \",14\"\n", rows, columns, gnuplot_quote(f.title));
  for (std::size_t p = 0; p < f.panels.size(); ++p) {
    body += fmt::format("set title {}\n", gnuplot_quote(f.panels[p].title));
    std::string plot = "plot ";
    for (std::size_t s = 0; s < series; ++s) {
      const double offset = (static_cast<double>(s) - (static_cast<double>(series) - 1) / 2) * width;
      if (s > 0) plot += ", \\\n     ";
      plot += fmt::format("$b{} using ($0 + ({})):{}:({}){} with boxes fillcolor \"{}\" title {}", p, plot_number(offset),
                          s + 2, plot_number(width), s == 0 ? ":xticlabels(1)" : "", palette_colour(static_cast<int>(s)),
                          gnuplot_quote(s < f.series.size() ? f.series[s] : ""));
    }
    body += f.panels[p].categories.empty() ? empty_panel_plot(f.empty_note) : plot + "\n";
  }
  body += "unset multiplot\n";
  return figure_script(script);
}

}  // namespace

RenderedFigure render_bar_figure(const BarFigure& f) { return render_figure(f.stem, bar_figure_script(f)); }

}  // namespace insmc::mc
