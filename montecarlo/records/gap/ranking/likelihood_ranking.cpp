#include "montecarlo/records/gap/ranking/likelihood_ranking.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <memory>
#include <span>
#include <string>
#include <utility>

#include "montecarlo/records/gap/fit/candidate_likelihood.h"
#include "montecarlo/records/gap/fit/likelihood_fit.h"
#include "montecarlo/records/gap/null/bootstrap.h"

namespace insmc::gap {
namespace {

using Selected = std::vector<std::vector<runs::Extension>>;

/// A candidate in a fitted model: its least-G fits on all runs and on each
/// half (their amplitudes are held there: a deterministic signature keeps
/// its least-squares size) and where the search of its other parameters
/// starts (every parameter, SI, in the candidate's order).
struct Member {
  const Candidate* candidate = nullptr;
  std::array<Choice, 3> fits;  ///< all runs, half 0, half 1
  std::vector<double> start;
};

std::vector<double> amplitudes(const Choice& choice) {
  return {choice.amplitude.data(), choice.amplitude.data() + choice.amplitude.size()};
}

std::string qualified(const std::vector<Member>& members, const Candidate& c, const std::string& name) {
  return members.size() > 1 ? c.name + "." + name : name;
}

/// The members' searched parameters in turn, each between its physical
/// limits, from its start (a grid's 0, "none", starts at the lower limit).
std::vector<FitParameter> fit_parameters(const std::vector<Member>& members) {
  std::vector<FitParameter> out;
  for (const Member& m : members)
    for (int j : likelihood_parameters(*m.candidate)) {
      const CandidateParameter& par = m.candidate->parameters[static_cast<std::size_t>(j)];
      out.push_back({qualified(members, *m.candidate, par.name), par.lower_si, par.upper_si,
                     std::clamp(m.start[static_cast<std::size_t>(j)], par.lower_si, par.upper_si)});
    }
  return out;
}

/// A model's lattices on p's runs: at[0] for all runs, at[1 + h] for half h,
/// each with the members' amplitudes of that fit, so that a held-out half
/// never enters its own prediction. Without amplitudes the three are one
/// lattice and every fit shares its memo.
struct Lattices {
  std::vector<std::unique_ptr<LikelihoodLattice>> own;
  std::array<LikelihoodLattice*, 3> at{};
  int evaluations() const {
    int e = 0;
    for (const auto& l : own) e += l->evaluations();
    return e;
  }
};

Lattices lattices(const runs::PreparedRuns& p, const std::vector<Member>& members, const Selected& none) {
  bool held = false;
  for (const Member& m : members) held = held || !m.candidate->amplitude_indices().empty();
  Lattices out;
  for (std::size_t k = 0; k < (held ? 3u : 1u); ++k) {
    std::vector<HeldCandidate> with;
    for (const Member& m : members) with.push_back({m.candidate, amplitudes(m.fits[k])});
    out.own.push_back(std::make_unique<LikelihoodLattice>(
        fit_parameters(members), joint_evaluation(p, std::move(with), none), static_cast<int>(p.runs.size())));
  }
  for (std::size_t k = 0; k < 3; ++k) out.at[k] = out.own[held ? k : 0].get();
  return out;
}

ProfileRange range(const ProfileInterval& ci) { return {ci.lower_si, ci.upper_si, ci.open_lower, ci.open_upper}; }

/// Every parameter of the members in their order: searched ones from the
/// likelihood fit, amplitudes from the least-squares fit on all runs.
std::vector<MlParameter> ml_parameters(const std::vector<Member>& members, const LikelihoodFit& fit, bool intervals) {
  std::vector<MlParameter> out;
  std::size_t next = 0;
  for (const Member& m : members) {
    const Candidate& c = *m.candidate;
    Eigen::Index amplitude = 0;
    for (const CandidateParameter& par : c.parameters) {
      MlParameter q;
      q.name = qualified(members, c, par.name);
      q.dimension = par.dimension;
      if (par.amplitude) {
        q.value = m.fits[0].amplitude[amplitude++];
        q.least_squares = true;
        q.at_limit = std::abs(q.value) >= par.upper_si;  // held at the magnitude it covers
      } else {
        const ParameterFit& f = fit.parameters[next++];
        q.value = f.value_si;
        q.at_limit = f.at_lower || f.at_upper;
        q.intervals = intervals;
        q.ci68 = range(f.ci68);
        q.ci95 = range(f.ci95);
      }
      out.push_back(std::move(q));
    }
  }
  return out;
}

/// A model on the records: its maximum likelihood on all runs and its
/// held-out gain. A single candidate gets profile intervals and a coarse
/// search over each whole range; a pair, warm-started from its members' own
/// fits, neither (a joint profile costs a search per point), and its folds
/// start from its fit on all runs.
LikelihoodResult fit_model(const runs::PreparedRuns& p, const std::vector<Member>& members, const Selected& none,
                           const std::vector<double>& null_ll) {
  const bool single = members.size() == 1;
  const Search search = single ? Search::kCoarse : Search::kLocal;
  Lattices l = lattices(p, members, none);
  const LikelihoodFit fit = fit_likelihood(*l.at[0], all_runs(p.runs.size()), single, search);
  LikelihoodResult r;
  r.fitted = true;
  r.parameters = ml_parameters(members, fit, single);
  // A pair's folds start from its fit on all runs, which lies near theirs.
  r.heldout_gain = cross_validate({l.at[1], l.at[2]}, null_ll, search, single ? std::span<const int>() : fit.index).gain;
  r.evaluations = l.evaluations();
  return r;
}

/// The same candidate's held-out gain on a null file q: amplitudes refitted
/// by least G on q's halves, as on the records.
double null_gain(const runs::PreparedRuns& q, std::vector<Member> members, const Selected& none,
                 const std::vector<double>& null_ll, const NullCalibration& m0) {
  for (Member& m : members) {
    if (m.candidate->amplitude_indices().empty()) continue;
    const std::array<Choice, 2> half = half_fits(evaluate_candidate(q, *m.candidate, none, m0), q.runs.size(), m0);
    m.fits = {Choice{}, half[0], half[1]};  // no fit on all runs: only the halves are scored
  }
  Lattices l = lattices(q, members, none);
  return cross_validate({l.at[1], l.at[2]}, null_ll).gain;
}

}  // namespace

LikelihoodRanking rank_by_likelihood(const std::vector<Scored>& ranked, const std::vector<std::string>& effects,
                                     const runs::PreparedRuns& p, const ModelNull& null, const DiagnosisOptions& options) {
  const auto& registry = candidates_of(options);
  const std::size_t top = std::min(ranked.size(), static_cast<std::size_t>(std::max(0, options.likelihood_candidates)));
  LikelihoodRanking out;
  if (top == 0) return out;
  out.candidates.resize(top);
  const Selected none(p.lattices.size());
  const std::vector<double> null_ll = null_log_likelihoods(p, none);

  // Models: the top candidates alone, then the pairs of the first few.
  std::vector<std::vector<Member>> models;
  for (std::size_t i = 0; i < top; ++i) {
    const Scored& s = ranked[i];
    const Candidate& c = registry[static_cast<std::size_t>(s.candidate)];
    models.push_back({{&c, {s.full_fit, s.half_fit[0], s.half_fit[1]}, parameter_values(c, s.full_fit)}});
  }
  const std::size_t paired = std::min(top, static_cast<std::size_t>(std::max(0, options.likelihood_pair_candidates)));
  const int files = null_file_count(p, null, options);
  std::atomic<std::uint64_t> done{0};
  const std::size_t pairs = paired * (paired - (paired > 0 ? 1 : 0)) / 2;
  const std::uint64_t total = top * static_cast<std::uint64_t>(1 + files) + pairs;
  const auto progress = [&] { report_progress(options, "maximum likelihood", ++done, total, "fits"); };

  // The candidates on the records first: a pair starts from its members' fits.
  tbb::parallel_for(std::size_t{0}, top, [&](std::size_t i) {
    out.candidates[i] = fit_model(p, models[i], none, null_ll);
    progress();
  });
  // A pair starts from each member's own maximum-likelihood values.
  for (std::size_t a = 0; a < paired; ++a)
    for (std::size_t b = a + 1; b < paired; ++b) {
      std::vector<Member> pair = {models[a][0], models[b][0]};
      for (std::size_t k : {a, b}) {
        std::vector<double>& start = pair[k == a ? 0 : 1].start;
        const std::vector<MlParameter>& fitted = out.candidates[k].parameters;
        for (std::size_t j = 0; j < start.size(); ++j) start[j] = fitted[j].value;
      }
      models.push_back(std::move(pair));
      out.pairs.push_back({effects[a], effects[b], {}});
    }
  // Then the pairs and, in the same parallel pass, each candidate's reference:
  // the same held-out gain on null files of the records' size. A pair's
  // reference is not measured: it would cost more than all the other fits
  // together (docs/gap-method.md §4).
  std::vector<runs::PreparedRuns> file(static_cast<std::size_t>(files));
  std::vector<std::vector<double>> file_null_ll(file.size());
  tbb::parallel_for(std::size_t{0}, file.size(), [&](std::size_t f) {
    file[f] = null_file(p, null, static_cast<int>(f));
    file_null_ll[f] = null_log_likelihoods(file[f], none);
  });
  std::vector<std::vector<double>> gains(top, std::vector<double>(file.size()));
  tbb::parallel_for(std::size_t{0}, pairs + top * file.size(), [&](std::size_t t) {
    if (t < pairs) {
      out.pairs[t].likelihood = fit_model(p, models[top + t], none, null_ll);
    } else {
      const std::size_t m = (t - pairs) % top, f = (t - pairs) / top;
      gains[m][f] = null_gain(file[f], models[m], none, file_null_ll[f], null.calibration);
    }
    progress();
  });
  for (std::size_t m = 0; m < top && !file.empty(); ++m) out.candidates[m].null_gain = quantile(gains[m], 0.5);

  std::stable_sort(out.pairs.begin(), out.pairs.end(), [](const PairResult& x, const PairResult& y) {
    return x.likelihood.heldout_gain > y.likelihood.heldout_gain;
  });
  return out;
}

}  // namespace insmc::gap
