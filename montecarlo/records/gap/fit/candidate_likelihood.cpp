#include "montecarlo/records/gap/fit/candidate_likelihood.h"

#include <map>

#include <memory>
#include <optional>
#include <utility>

#include "lib/common/assert.h"
#include "montecarlo/records/gap/candidates/layout_extensions.h"
#include "montecarlo/records/runs/model/likelihood.h"

namespace insmc::gap {

namespace {

/// Every run's log-likelihood under per-layout models (`extension(L)`: the
/// extensions added for layout L, none for the null). Each layout's
/// model is built and factorized once, and only for layouts some run uses.
std::vector<double> per_run(const runs::PreparedRuns& p, const std::vector<std::vector<runs::Extension>>& selected,
                            const std::vector<std::vector<runs::Extension>>& added) {
  // Keyed by layout and the run's rows: a run that stops early has the
  // marginal likelihood of the layout's first rows.
  // Each lattice's model combined and factorized once, each layout's cut
  // from it (likelihood.h).
  std::map<std::size_t, runs::LatticeLikelihood> on_lattice;
  std::map<std::pair<std::size_t, std::size_t>, runs::RunLikelihood> models;
  std::vector<double> out(p.runs.size());
  for (std::size_t r = 0; r < p.runs.size(); ++r) {
    const auto L = static_cast<std::size_t>(p.layout_of[r]);
    const std::pair<std::size_t, std::size_t> key{L, p.runs[r].values.size()};
    auto it = models.find(key);
    if (it == models.end()) {
      const auto l = static_cast<std::size_t>(p.lattice_of[L]);
      auto lattice = on_lattice.find(l);
      if (lattice == on_lattice.end()) {
        std::vector<const runs::Extension*> extensions;
        for (const runs::Extension& e : selected[l]) extensions.push_back(&e);
        for (const runs::Extension& e : added[l]) extensions.push_back(&e);
        lattice = on_lattice.emplace(l, runs::LatticeLikelihood(runs::combine(p.lattice_bases[l], extensions))).first;
      }
      // A run that stops early: the layout's first rows (their marginal).
      const std::span<const Eigen::Index> rows(p.lattice_rows[L].data(), key.second);
      it = models.emplace(key, runs::RunLikelihood(lattice->second, rows)).first;
    }
    out[r] = it->second.log_likelihood(run_values(p.runs[r]));
  }
  return out;
}

}  // namespace

std::vector<int> likelihood_parameters(const Candidate& c) {
  std::vector<int> searched;
  for (std::size_t j = 0; j < c.parameters.size(); ++j)
    if (!c.parameters[j].amplitude) searched.push_back(static_cast<int>(j));
  return searched;
}

RunLogLikelihoods joint_evaluation(const runs::PreparedRuns& p, std::vector<HeldCandidate> candidates,
                                   const std::vector<std::vector<runs::Extension>>& selected) {
  INSMC_ASSERT(selected.size() == p.lattices.size(), "selected effects for {} lattices, expected {}", selected.size(),
               p.lattices.size());
  // Each candidate's layout contexts live as long as the function: candidates
  // cache unit responses in them, which every later evaluation reuses.
  auto contexts = std::make_shared<std::vector<LayoutExtensions>>();
  std::size_t searched = 0;
  for (const HeldCandidate& h : candidates) {
    contexts->emplace_back(p);
    searched += likelihood_parameters(*h.candidate).size();
  }
  return [&p, &selected, contexts, candidates = std::move(candidates), searched](std::span<const double> values) {
    INSMC_ASSERT(values.size() == searched, "{} values for {} parameters", values.size(), searched);
    // Each candidate's parameter vector: its searched values in turn, its amplitudes held.
    std::vector<std::vector<double>> theta;
    std::size_t next = 0;
    for (const HeldCandidate& h : candidates) {
      const Candidate& c = *h.candidate;
      std::vector<double>& t = theta.emplace_back(c.parameters.size(), 0.0);
      for (int j : likelihood_parameters(c)) t[static_cast<std::size_t>(j)] = values[next++];
      const std::vector<int> amp = c.amplitude_indices();
      for (std::size_t j = 0; j < h.amplitudes.size() && j < amp.size(); ++j)
        t[static_cast<std::size_t>(amp[j])] = h.amplitudes[j];
    }
    const std::vector<bool> used = used_layouts(p);
    std::vector<std::vector<runs::Extension>> added(p.lattices.size());
    for (std::size_t i = 0; i < candidates.size(); ++i) {
      std::vector<std::optional<runs::Extension>> built = (*contexts)[i].build(*candidates[i].candidate, theta[i], used);
      for (std::size_t l = 0; l < p.lattices.size(); ++l)
        if (built[l]) added[l].push_back(std::move(*built[l]));
    }
    return per_run(p, selected, added);
  };
}

RunLogLikelihoods candidate_evaluation(const runs::PreparedRuns& p, const Candidate& c,
                                       const std::vector<std::vector<runs::Extension>>& selected) {
  return joint_evaluation(p, {{&c, {}}}, selected);
}

std::vector<double> null_log_likelihoods(const runs::PreparedRuns& p,
                                         const std::vector<std::vector<runs::Extension>>& selected) {
  return per_run(p, selected, std::vector<std::vector<runs::Extension>>(p.lattices.size()));
}

}  // namespace insmc::gap
