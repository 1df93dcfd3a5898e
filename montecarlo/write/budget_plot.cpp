#include "montecarlo/write/budget_plot.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include <fmt/format.h>

#include "montecarlo/write/csv.h"

namespace insmc::mc {

BarFigure budget_figure(const StudyConfig& c, const StudyLayout& l, const StudyMap& map) {
  const std::vector<std::string> sources = map.budget_sources();
  const std::vector<std::vector<double>> shares = map.budget_shares();
  const double last_s = c.report_times_s.back();
  BarFigure f;
  f.stem = "budget";
  f.title = fmt::format("Error budget: shares of the horizontal mean-square error at {} min, fidelity {}",
                        format_number(last_s / 60), to_string(c.map_fidelity()));
  f.y_label = "share of E[r²]";
  f.empty_note = "no error source: the horizontal error is zero";
  for (System s : c.systems) f.series.push_back(fmt::format("system {}", system_number(s)));
  for (Scheme scheme : c.schemes) {
    // The horizontal output at the last report time, per system.
    std::vector<std::size_t> outputs;
    for (System system : c.systems)
      for (std::size_t o = 0; o < l.outputs.size(); ++o) {
        const OutputSpec& spec = l.outputs[o];
        if (spec.scheme == scheme && spec.system == system && spec.axis == Axis::kHorizontal &&
            std::abs(l.times_s[spec.time_index] - last_s) < 1e-6)
          outputs.push_back(o);
      }
    if (outputs.size() != c.systems.size()) continue;
    std::vector<std::size_t> order(sources.size());
    std::iota(order.begin(), order.end(), 0);
    const auto largest = [&](std::size_t p) {
      double m = 0;
      for (std::size_t o : outputs) m = std::max(m, shares[o][p]);
      return m;
    };
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return largest(a) > largest(b); });
    BarPanel panel;
    panel.title = std::string(to_string(scheme));
    panel.values.resize(outputs.size());
    for (std::size_t i = 0; i < order.size() && panel.categories.size() < kBudgetPlotSources; ++i) {
      if (!(largest(order[i]) > 0)) break;
      panel.categories.push_back(sources[order[i]]);
      for (std::size_t s = 0; s < outputs.size(); ++s) panel.values[s].push_back(shares[outputs[s]][order[i]]);
    }
    f.panels.push_back(std::move(panel));
  }
  return f;
}

}  // namespace insmc::mc
