#include "montecarlo/gap/fit/candidate_likelihood.h"

#include <memory>
#include <optional>

#include "lib/common/assert.h"
#include "montecarlo/gap/model/likelihood.h"

namespace insmc::mc {

namespace {

/// Every run's log-likelihood under per-layout models (`extension(L)`: the
/// candidate's extension for layout L, or null for none). Each layout's
/// model is built and factorized once, and only for layouts some run uses.
template <class ExtensionOf>
std::vector<double> per_run(const PreparedRuns& p, const std::vector<std::vector<gap::Extension>>& selected,
                            const ExtensionOf& extension) {
  std::vector<std::optional<gap::RunLikelihood>> models(p.layouts.size());
  std::vector<double> out(p.runs.size());
  for (std::size_t r = 0; r < p.runs.size(); ++r) {
    const auto L = static_cast<std::size_t>(p.layout_of[r]);
    if (!models[L]) {
      std::vector<const gap::Extension*> extensions;
      for (const gap::Extension& e : selected[L]) extensions.push_back(&e);
      const std::optional<gap::Extension> added = extension(L);
      if (added) extensions.push_back(&*added);
      models[L].emplace(gap::combine(p.bases[L], extensions));
    }
    out[r] = models[L]->log_likelihood(run_values(p.runs[r]));
  }
  return out;
}

}  // namespace

std::vector<int> likelihood_parameters(const gap::Candidate& c) {
  std::vector<int> searched;
  for (std::size_t j = 0; j < c.parameters.size(); ++j)
    if (!c.parameters[j].amplitude) searched.push_back(static_cast<int>(j));
  return searched;
}

RunLogLikelihoods candidate_evaluation(const PreparedRuns& p, const gap::Candidate& c,
                                       const std::vector<std::vector<gap::Extension>>& selected) {
  INSMC_ASSERT(selected.size() == p.layouts.size(), "selected effects for {} layouts, expected {}", selected.size(),
               p.layouts.size());
  // The layouts' contexts live as long as the function: candidates cache
  // unit responses in them, which every later evaluation reuses.
  auto contexts = std::make_shared<std::vector<gap::LayoutContext>>(p.layouts.size());
  for (std::size_t L = 0; L < p.layouts.size(); ++L) (*contexts)[L] = {&p.layouts[L], &p.site, &p.bases[L], {}};
  return [&p, &c, &selected, contexts, searched = likelihood_parameters(c)](std::span<const double> values) {
    INSMC_ASSERT(values.size() == searched.size(), "{}: {} values for {} parameters", c.name, values.size(),
                 searched.size());
    std::vector<double> theta(c.parameters.size(), 0.0);  // amplitudes 0
    for (std::size_t j = 0; j < searched.size(); ++j) theta[static_cast<std::size_t>(searched[j])] = values[j];
    return per_run(p, selected, [&](std::size_t L) { return std::optional(c.build((*contexts)[L], theta)); });
  };
}

std::vector<double> null_log_likelihoods(const PreparedRuns& p,
                                         const std::vector<std::vector<gap::Extension>>& selected) {
  return per_run(p, selected, [](std::size_t) { return std::optional<gap::Extension>(); });
}

}  // namespace insmc::mc
