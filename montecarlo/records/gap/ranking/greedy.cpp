#include "montecarlo/records/gap/ranking/greedy.h"

#include <algorithm>
#include <fmt/format.h>
#include <string>
#include <vector>

#include "lib/units/quantity.h"
#include "lib/units/quantity_display.h"
#include "montecarlo/records/gap/candidates/layout_extensions.h"
#include "montecarlo/records/gap/null/bootstrap.h"
#include "montecarlo/records/gap/ranking/ranking.h"

namespace insmc::gap {
namespace {

std::string fmt_params(const std::vector<ParameterEstimate>& ps) {
  std::string s;
  for (const ParameterEstimate& e : ps) s += (s.empty() ? "" : ", ") + e.name + "=" + format_quantity_rounded(e.value, e.dimension);
  return s;
}

/// A greedy step must close at least this share of the held-out gap left
/// above the null's critical G (docs/gap-method.md, "Greedy shrink"): a
/// candidate that closes less describes a sliver of data that the model and
/// the candidates do not describe, and each step adds its columns to every
/// model the next ranking fits.
constexpr double kMinShareClosed = 1.0 / 3;

/// The share of what is left (before − the critical G) that a step to
/// `after` closes; 1 when nothing is left above the critical G.
double share_closed(double before, double after, double critical) {
  const double left = before - critical;
  return left > 0 ? (before - after) / left : 1.0;
}

}  // namespace

Selection rank_and_select(const Diagnosis& verdict, const runs::PreparedRuns& p, const ModelNull& null,
                          const DiagnosisOptions& options) {
  const auto& registry = candidates_of(options);
  Selection d;
  std::vector<std::vector<runs::Extension>> selected(p.lattices.size());  // per lattice
  std::vector<std::string> taken;
  double before = verdict.heldout_gap_before;
  for (int step = 0; step < std::max(1, options.max_selected); ++step) {
    const RankedCandidates candidates = rank_candidates(p, selected, taken, null, options,
                                                        fmt::format("candidates, step {}", step + 1), step == 0);
    const std::vector<Scored>& ranked = candidates.ranked;
    if (ranked.empty()) break;
    if (step == 0) {
      d.first = first_ranking(candidates, p, null, options, before);
    }
    if (!verdict.model_gap_significant()) break;
    const Scored& best = ranked.front();
    const Candidate& c = registry[static_cast<std::size_t>(best.candidate)];
    if (step > 0 && best.heldout_gap >= before) break;  // nothing left that helps on held-out runs
    const double closed = share_closed(before, best.heldout_gap, verdict.model_null_gap_critical());
    if (step > 0 && closed < kMinShareClosed) {
      d.statements.push_back(fmt::format("the next candidate, {}, closes {:.0f} % of the held-out gap left above the "
                                         "null's critical value (less than {:.0f} %): the greedy search stops after {} "
                                         "effect(s)", c.name, 100 * closed, 100 * kMinShareClosed, step));
      break;
    }
    const double left = signed_gap(log_ratios(pool(best.heldout, all_runs(p.runs.size())),
                                                        null.calibration, CoherentReference::kAtLeastModelScatter))
                            .unmodelled;
    GreedyStep g{c.name, best.parameters, best.heldout_gap, p_value_of(left, null.unmodelled)};
    d.greedy.push_back(g);
    d.selected.push_back(step == 0 ? d.first.top : c.name);
    taken.push_back(c.name);
    const std::vector<double> theta = parameter_values(c, best.full_fit);
    std::vector<std::optional<runs::Extension>> built = LayoutExtensions(p).build(c, theta);
    for (std::size_t l = 0; l < p.lattices.size(); ++l)
      if (built[l]) selected[l].push_back(std::move(*built[l]));
    before = best.heldout_gap;
    if (g.p_value >= options.alpha) break;  // no significant gap remains
    if (step + 1 == options.max_selected) {
      d.statements.push_back(fmt::format("a significant gap remains after {} effects ({}); the greedy search stops "
                                         "there", step + 1, fmt_params(best.parameters)));
    } else if (closed < kMinShareClosed) {  // the first effect: kept (the ranking's top), but no further step
      d.statements.push_back(fmt::format("the top candidate closes {:.0f} % of the held-out gap above the null's "
                                         "critical value (less than {:.0f} %): the data lie far outside what the "
                                         "candidates describe, and the greedy search stops after it",
                                         100 * closed, 100 * kMinShareClosed));
      break;
    }
  }
  return d;
}

}  // namespace insmc::gap
