#include "montecarlo/study/write/budget_plot.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string_view>
#include <utility>

#include <fmt/format.h>

#include "lib/uncertainty/catalogue.h"
#include "montecarlo/report/csv.h"

namespace insmc::mc {
namespace {

/// A source's name on the figure: words and the paper's symbol
/// (gyro_drift_x → "gyro drift x (ω_dox)"); the tables keep the catalogue name.
std::string readable_source(const std::string& name) {
  static const std::pair<std::string_view, std::string_view> kOthers[] = {
      {"position_resolution", "position resolution"}, {"dv_pulses", "Δv pulse quantization"},
      {"sway", "vehicle sway"}, {"torquer_pulses", "torquer pulse quantization"},
      {"alignment_dv_pulses", "Δv pulses in alignment"}, {"mean", "mean of the sample"}};
  for (const auto& [key, text] : kOthers)
    if (name == key) return std::string(text);
  const std::string_view realigned = "realignment:";
  const bool at_realignment = name.starts_with(realigned);
  const std::string base = at_realignment ? name.substr(realigned.size()) : name;
  std::string words = base;
  std::replace(words.begin(), words.end(), '_', ' ');
  for (const UncertaintySpec& spec : catalogue())
    if (spec.name == base) words += fmt::format(" ({})", spec.symbol);
  return at_realignment ? words + " at realignment" : words;
}

}  // namespace

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
      panel.categories.push_back(readable_source(sources[order[i]]));
      for (std::size_t s = 0; s < outputs.size(); ++s) panel.values[s].push_back(shares[outputs[s]][order[i]]);
    }
    f.panels.push_back(std::move(panel));
  }
  return f;
}

}  // namespace insmc::mc
