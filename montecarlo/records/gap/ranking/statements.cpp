#include "montecarlo/records/gap/ranking/statements.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <string>

#include "lib/units/quantity.h"
#include "lib/units/quantity_display.h"
#include "montecarlo/records/gap/candidates/candidates.h"

namespace insmc::gap {

std::string what_tells_apart(const std::string& a, const std::string& b) {
  const auto test_of = [](const std::string& name) {
    for (const Candidate& c : candidate_registry())
      if (c.name == name) return c.told_apart_by;
    return std::string();
  };
  const std::string ta = test_of(a), tb = test_of(b);
  if (ta.empty() || tb.empty()) return "more runs would tell them apart";
  if (ta == tb) return "what would tell them apart: " + ta;
  return fmt::format("what would tell them apart: for {}, {}; for {}, {}", a, ta, b, tb);
}

std::vector<std::string> ranking_limits(const Diagnosis& d) {
  std::vector<std::string> out;
  if (!d.ranked() || !d.model_gap_significant()) return out;
  const CandidateResult& top = d.first.ranking.front();
  for (const ParameterEstimate& p : top.parameters)
    if (p.at_grid_edge)
      out.push_back(fmt::format("the top candidate's {} is fitted at the edge of its range ({}): the data lie "
                                "beyond what this candidate covers, so the ranking shows a direction, not a "
                                "fitted effect", p.name, format_quantity_rounded(p.value, p.dimension)));
  const double left = d.greedy.empty() ? top.heldout_gap_after : d.greedy.back().heldout_gap;
  if (!d.greedy.empty() && d.greedy.back().p_value < d.alpha && left > 3.0 * d.model_null_gap_critical())
    out.push_back(fmt::format("after {} effect(s) the held-out gap is still G = {:.3g}, over three times the "
                              "null's critical {:.3g}: no candidate (alone or combined) explains these data; "
                              "the system lies far outside the model's priors or has disturbances the "
                              "candidates do not describe", d.greedy.size(), left, d.model_null_gap_critical()));
  for (const CandidateResult& c : d.first.ranking) {
    if (c.effect != "bounds" || c.parameters.empty()) continue;
    const bool chosen = std::find(d.selected.begin(), d.selected.end(), c.effect) != d.selected.end() ||
                        d.first.top.find(c.effect) != std::string::npos;
    if (chosen && c.shrink > 0.1)
      out.push_back(fmt::format("priors wider than Table 3.1 by a factor {} (bounds) remove {:.0f} % of the "
                                "held-out gap: Table 3.1's priors are too narrow for this system",
                                c.parameters.front().value, 100 * c.shrink));
  }
  // Candidates that change nothing on held-out runs: with these records they
  // are either absent or masked by what is present (not identifiable here).
  std::string traceless;
  for (const CandidateResult& c : d.first.ranking)
    if (std::abs(c.shrink) < 0.01) traceless += (traceless.empty() ? "" : ", ") + c.effect;
  if (!traceless.empty())
    out.push_back(fmt::format("no held-out trace (|shrink| < 1 %): {}; with these records they are absent "
                              "or masked by what is present, so the data say nothing about them", traceless));
  if (d.first.top.find('|') != std::string::npos)
    out.push_back(fmt::format("{} are not told apart by these data (held-out margin {:.3g} ± {:.3g}): "
                              "reported as one class; {}", d.first.top, d.first.runner_up_margin, d.first.runner_up_margin_se,
                              what_tells_apart(d.first.ranking[0].effect, d.first.ranking[1].effect)));
  return out;
}

}  // namespace insmc::gap
