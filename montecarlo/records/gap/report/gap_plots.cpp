#include "montecarlo/records/gap/report/gap_plots.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "lib/units/units.h"
#include "montecarlo/report/plot/palette.h"
#include "montecarlo/report/plot/panel_figure.h"

namespace insmc::gap {
namespace {

/// Which side of the null band an observed ln ratio lies on: the legend's
/// three entries.
enum class Side { kAbove, kBelow, kInside };

Side side_of(const GroupResult& g) {
  return g.log_ratio > g.null_high ? Side::kAbove : g.log_ratio < g.null_low ? Side::kBelow : Side::kInside;
}

}  // namespace

std::string groups_figure_script(const Diagnosis& d) {
  const std::size_t n = d.where.groups.size();
  std::string data = "$band << EOD\n";
  for (std::size_t i = 0; i < n; ++i)
    data += fmt::format("{} {} {}\n", i + 1, mc::plot_number(d.where.groups[i].null_low), mc::plot_number(d.where.groups[i].null_high));
  data += "EOD\n";
  // The sensor's own noise through the import, on the same scale (verdict 2's null).
  bool own_noise = false;
  data += "$own << EOD\n";
  for (std::size_t i = 0; i < n; ++i)
    if (std::isfinite(d.where.groups[i].own_noise_low)) {
      own_noise = true;
      data += fmt::format("{} {} {}\n", i + 1, mc::plot_number(d.where.groups[i].own_noise_low),
                          mc::plot_number(d.where.groups[i].own_noise_high));
    }
  data += "NaN NaN NaN\nEOD\n";
  static constexpr Side kSides[] = {Side::kAbove, Side::kBelow, Side::kInside};
  for (const Side s : kSides) {
    data += fmt::format("$side{} << EOD\n", static_cast<int>(s));
    for (std::size_t i = 0; i < n; ++i)
      if (side_of(d.where.groups[i]) == s) data += fmt::format("{} {}\n", i + 1, mc::plot_number(d.where.groups[i].log_ratio));
    // An empty block would stop gnuplot's plot: a missing point keeps the legend entry.
    data += "NaN NaN\nEOD\n";
  }
  std::string settings = data;
  settings += "set xtics rotate by -60 font \",9\" (";
  for (std::size_t i = 0; i < n; ++i)
    settings += fmt::format("{}{} {}", i ? ", " : "", mc::gnuplot_quote(d.where.groups[i].name()), i + 1);
  settings += ")\n";
  settings += fmt::format("set xrange [0.3:{}]\nset xzeroaxis linecolor \"#888888\"\n", mc::plot_number(static_cast<double>(n) + 0.7));
  settings += "set grid ytics linecolor \"#dddddd\"\nset offsets 0, 0, graph 0.08, graph 0.08\n";
  settings += "set ylabel \"ln(observed / expected) of the group\"\nset xlabel \"group (stage, axis, window)\"\n";
  settings += "set key outside below horizontal font \",9\"\n";
  const double alpha = d.alpha;
  std::string body = n == 0 ? mc::empty_panel_plot("no groups to show")
                            : fmt::format(
                                  "plot $band using 1:(($2+$3)/2):($1-0.35):($1+0.35):2:3 with boxxyerror fillstyle solid "
                                  "0.5 noborder fillcolor \"#bbbbbb\" title {}, \\\n{}"
                                  "     $side0 using 1:2 with impulses linewidth 2 linecolor \"{}\" notitle, \\\n"
                                  "     $side0 using 1:2 with points pointtype 7 pointsize 0.8 linecolor \"{}\" title {}, \\\n"
                                  "     $side1 using 1:2 with impulses linewidth 2 linecolor \"{}\" notitle, \\\n"
                                  "     $side1 using 1:2 with points pointtype 7 pointsize 0.8 linecolor \"{}\" title {}, \\\n"
                                  "     $side2 using 1:2 with impulses linewidth 2 linecolor \"#333333\" notitle, \\\n"
                                  "     $side2 using 1:2 with points pointtype 7 pointsize 0.8 linecolor \"#333333\" title {}\n",
                                  mc::gnuplot_quote(fmt::format("the model's null files: band (two-sided, alpha {:g})", alpha)),
                                  own_noise ? fmt::format("     $own using 1:(($2+$3)/2):($1-0.18):($1+0.18):2:3 with "
                                                          "boxxyerror fillstyle transparent solid 0.45 noborder "
                                                          "fillcolor \"#6fa8dc\" title {}, \\\n",
                                                          mc::gnuplot_quote(fmt::format(
                                                              "the sensor's own noise through the import: band (alpha {:g})",
                                                              alpha)))
                                            : std::string(),
                                  mc::palette_colour(1), mc::palette_colour(1),
                                  mc::gnuplot_quote("above the model's band: more than the model"), mc::palette_colour(0),
                                  mc::palette_colour(0), mc::gnuplot_quote("below the model's band: less than the model"),
                                  mc::gnuplot_quote("inside the model's band"));
  const int width = std::clamp(260 + 20 * static_cast<int>(n), 900, 1600);
  const std::string title =
      own_noise ? "Against the model (verdict 1), with the band of the sensor's own noise (verdict 2): ln(observed/expected) per group"
                : "Where the records depart from the model: ln(observed/expected) per group, against the model's null files";
  mc::FigureScript script{"gap_groups", title,
                      settings + "set title " + mc::gnuplot_quote(title) + " font \",12\"\n", body, width, 640};
  return mc::figure_script(script);
}

mc::PanelFigure allan_figure(const Diagnosis& d) {
  bool own_noise = false;
  for (const AllanCurve& c : d.where.allan)
    for (const AllanPoint& p : c.points) own_noise = own_noise || p.own_noise > 0;
  mc::PanelFigure f;
  f.stem = "gap_allan";
  f.title = "Allan deviation of the f residuals: data (solid) and null runs (dashed, shaded: 5-95 % of null files)";
  f.x_label = "cluster time τ [s]";
  f.y_label = "Allan deviation [µg]";
  f.log_x = f.log_y = true;
  f.columns = 1;
  // One panel per verdict, each with the band of the null it is judged against.
  const auto panel_of = [&](bool against_own_noise) {
    mc::PlotPanel panel;
    panel.title = against_own_noise ? "against the unit's own noise (verdict 2): null runs through the import"
                                    : own_noise ? "against the model (verdict 1): the model's null runs"
                                                : "against the model: the model's null runs";
    for (const AllanCurve& c : d.where.allan) {
      mc::PlotLine data, null;
      data.name = fmt::format("f_{} data", "xyz"[c.axis % 3]);
      null.name = fmt::format("f_{} {}", "xyz"[c.axis % 3], against_own_noise ? "own-noise null" : "model null");
      data.colour = null.colour = c.axis;
      null.dashed = true;
      for (const AllanPoint& p : c.points) {
        const double mid = against_own_noise ? p.own_noise : p.null;
        const double low = against_own_noise ? p.own_noise_low : p.null_low;
        const double high = against_own_noise ? p.own_noise_high : p.null_high;
        if (!(p.cluster_s > 0 && p.observed > 0 && mid > 0)) continue;
        data.x.push_back(p.cluster_s);
        data.y.push_back(p.observed / kUgToMps2);
        data.marks.push_back({p.cluster_s, p.observed / kUgToMps2, p.observed / kUgToMps2, p.observed / kUgToMps2});
        null.x.push_back(p.cluster_s);
        null.y.push_back(mid / kUgToMps2);
        null.lo.push_back(std::min(low > 0 ? low : mid, mid) / kUgToMps2);
        null.hi.push_back(std::max(high, mid) / kUgToMps2);
      }
      if (data.x.empty()) continue;
      panel.lines.push_back(std::move(null));
      panel.lines.push_back(std::move(data));
    }
    return panel;
  };
  f.panels.push_back(panel_of(false));
  if (own_noise) f.panels.push_back(panel_of(true));
  return f;
}

}  // namespace insmc::gap
