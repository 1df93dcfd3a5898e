#include "montecarlo/gap/report/gap_plots.h"

#include <algorithm>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "lib/units/units.h"
#include "montecarlo/write/plot/palette.h"
#include "montecarlo/write/plot/panel_figure.h"

namespace insmc::gap {
namespace {

/// Which side of the null band an observed ln ratio lies on: the legend's
/// three entries.
enum class Side { kAbove, kBelow, kInside };

Side side_of(const GroupResult& g) {
  return g.log_ratio > g.null_high ? Side::kAbove : g.log_ratio < g.null_low ? Side::kBelow : Side::kInside;
}

}  // namespace

mc::RenderedFigure render_groups_figure(const Diagnosis& d) {
  const std::size_t n = d.groups.size();
  std::string data = "$band << EOD\n";
  for (std::size_t i = 0; i < n; ++i)
    data += fmt::format("{} {} {}\n", i + 1, mc::plot_number(d.groups[i].null_low), mc::plot_number(d.groups[i].null_high));
  data += "EOD\n";
  static constexpr Side kSides[] = {Side::kAbove, Side::kBelow, Side::kInside};
  for (const Side s : kSides) {
    data += fmt::format("$side{} << EOD\n", static_cast<int>(s));
    for (std::size_t i = 0; i < n; ++i)
      if (side_of(d.groups[i]) == s) data += fmt::format("{} {}\n", i + 1, mc::plot_number(d.groups[i].log_ratio));
    // An empty block would stop gnuplot's plot: a missing point keeps the legend entry.
    data += "NaN NaN\nEOD\n";
  }
  std::string settings = data;
  settings += "set xtics rotate by -60 font \",9\" (";
  for (std::size_t i = 0; i < n; ++i)
    settings += fmt::format("{}{} {}", i ? ", " : "", mc::gnuplot_quote(d.groups[i].name()), i + 1);
  settings += ")\n";
  settings += fmt::format("set xrange [0.3:{}]\nset xzeroaxis linecolor \"#888888\"\n", mc::plot_number(static_cast<double>(n) + 0.7));
  settings += "set grid ytics linecolor \"#dddddd\"\nset offsets 0, 0, graph 0.08, graph 0.08\n";
  settings += "set ylabel \"ln(observed / expected) of the group\"\nset xlabel \"group (stage, axis, window)\"\n";
  settings += "set key outside below horizontal font \",9\"\n";
  const double alpha = d.alpha;
  std::string body = n == 0 ? mc::empty_panel_plot("no groups to show")
                            : fmt::format(
                                  "plot $band using 1:(($2+$3)/2):($1-0.35):($1+0.35):2:3 with boxxyerror fillstyle solid "
                                  "0.5 noborder fillcolor \"#bbbbbb\" title {}, \\\n"
                                  "     $side0 using 1:2 with impulses linewidth 2 linecolor \"{}\" notitle, \\\n"
                                  "     $side0 using 1:2 with points pointtype 7 pointsize 0.8 linecolor \"{}\" title {}, \\\n"
                                  "     $side1 using 1:2 with impulses linewidth 2 linecolor \"{}\" notitle, \\\n"
                                  "     $side1 using 1:2 with points pointtype 7 pointsize 0.8 linecolor \"{}\" title {}, \\\n"
                                  "     $side2 using 1:2 with impulses linewidth 2 linecolor \"#333333\" notitle, \\\n"
                                  "     $side2 using 1:2 with points pointtype 7 pointsize 0.8 linecolor \"#333333\" title {}\n",
                                  mc::gnuplot_quote(fmt::format("null files' band (two-sided, alpha {:g})", alpha)),
                                  mc::palette_colour(1), mc::palette_colour(1),
                                  mc::gnuplot_quote("above the band: more than the model"), mc::palette_colour(0),
                                  mc::palette_colour(0), mc::gnuplot_quote("below the band: less than the model"),
                                  mc::gnuplot_quote("inside the band"));
  const int width = std::clamp(260 + 20 * static_cast<int>(n), 900, 1600);
  mc::FigureScript script{"gap_groups", "Where the records depart from the model: ln(observed/expected) per group",
                      settings + "set title " +
                          mc::gnuplot_quote("Where the records depart from the model: ln(observed/expected) per group") +
                          " font \",13\"\n",
                      body, width, 640};
  return mc::render_figure(script.stem, mc::figure_script(script));
}

mc::RenderedFigure render_allan_figure(const Diagnosis& d) {
  mc::PanelFigure f;
  f.stem = "gap_allan";
  f.title = "Allan deviation of the f residuals: data (solid) and null runs (dashed, shaded: 5-95 % of null files)";
  f.x_label = "cluster time τ [s]";
  f.y_label = "Allan deviation [µg]";
  f.log_x = f.log_y = true;
  f.columns = 1;
  mc::PlotPanel panel;
  panel.title = "specific-force residuals, per axis";
  for (const AllanCurve& c : d.allan) {
    mc::PlotLine data, null;
    data.name = fmt::format("f_{} data", "xyz"[c.axis % 3]);
    null.name = fmt::format("f_{} null runs", "xyz"[c.axis % 3]);
    data.colour = null.colour = c.axis;
    null.dashed = true;
    for (const AllanPoint& p : c.points) {
      if (!(p.cluster_s > 0 && p.observed > 0 && p.null > 0)) continue;
      data.x.push_back(p.cluster_s);
      data.y.push_back(p.observed / kUgToMps2);
      data.marks.push_back({p.cluster_s, p.observed / kUgToMps2, p.observed / kUgToMps2, p.observed / kUgToMps2});
      null.x.push_back(p.cluster_s);
      null.y.push_back(p.null / kUgToMps2);
      null.lo.push_back(std::min(p.null_low > 0 ? p.null_low : p.null, p.null) / kUgToMps2);
      null.hi.push_back(std::max(p.null_high, p.null) / kUgToMps2);
    }
    if (data.x.empty()) continue;
    panel.lines.push_back(std::move(null));
    panel.lines.push_back(std::move(data));
  }
  f.panels.push_back(std::move(panel));
  return mc::render_panel_figure(f);
}

}  // namespace insmc::gap
