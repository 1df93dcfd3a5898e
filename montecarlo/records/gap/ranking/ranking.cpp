#include "montecarlo/records/gap/ranking/ranking.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <numeric>
#include <string>
#include <utility>

#include "montecarlo/records/gap/fit/subgrid.h"
#include "montecarlo/records/gap/null/bootstrap.h"
#include "montecarlo/records/gap/ranking/effect_terms.h"
#include "montecarlo/records/gap/ranking/likelihood_ranking.h"

namespace insmc::gap {
namespace {

/// Every run under the other half's fit (runs alternate between the halves
/// in file order): 2-fold cross-validation.
RunSet heldout_set(const std::array<Choice, 2>& half, CandidateSums& s, const std::vector<int>& runs) {
  keep_keyed_at(s, {half[0].grid, half[1].grid});
  std::vector<Choice> heldout_choice(runs.size());
  for (std::size_t r = 0; r < runs.size(); ++r) heldout_choice[r] = half[1 - r % 2];
  return run_set_under(s, runs, heldout_choice);
}

/// The runs first, first + 1, ..., first + n - 1.
std::vector<int> run_range(std::size_t first, std::size_t n) {
  std::vector<int> runs(n);
  std::iota(runs.begin(), runs.end(), static_cast<int>(first));
  return runs;
}

/// 2-fold cross-validation (runs alternate between the halves in file order),
/// the full-data fit and its resampled 16–84 % range.
Scored score(const Candidate& c, CandidateSums s, std::size_t n, const NullCalibration& m0,
             std::uint64_t seed, const runs::RecordSite& site) {
  const auto in_effect_terms = [&](std::vector<double> theta) {
    if (c.to_effect_terms) c.to_effect_terms(theta, site);
    return theta;
  };
  Scored out;
  out.half_fit = half_fits(s, n, m0);
  out.heldout = heldout_set(out.half_fit, s, all_runs(n));
  out.heldout_gap = gap_value(out.heldout, all_runs(n), m0);
  out.full_fit = choose(s, all_runs(n), m0);
  const std::vector<double> best = parameter_values(c, out.full_fit);
  // Reported between grid points (fit/subgrid.h), so that the resampled
  // fits spread as the data do, not only from one grid point to the next.
  const std::vector<double> reported =
      in_effect_terms(subgrid_values(c, RunsUnderChoice(s, all_runs(n)), out.full_fit, m0));
  constexpr int kResamples = 200;
  std::vector<std::vector<double>> draws(c.parameters.size());
  for (int b = 0; b < kResamples; ++b) {
    const RunsUnderChoice runs(
        s, resample(seed, 1'000'000 + static_cast<std::uint64_t>(b), static_cast<int>(n), static_cast<int>(n)));
    const std::vector<double> theta = in_effect_terms(subgrid_values(c, runs, choose(runs, m0), m0));
    for (std::size_t i = 0; i < theta.size(); ++i) draws[i].push_back(theta[i]);
  }
  for (std::size_t i = 0; i < c.parameters.size(); ++i) {
    const CandidateParameter& par = c.parameters[i];
    ParameterEstimate e{par.name, par.dimension, reported[i], quantile(draws[i], 0.16), quantile(draws[i], 0.84),
                        par.amplitude ? std::abs(best[i]) >= par.grid.front()
                                      : par.grid.size() > 1 && (best[i] == par.grid.front() || best[i] == par.grid.back()),
                        {}};
    out.parameters.push_back(e);
  }
  return out;
}

}  // namespace

std::array<Choice, 2> half_fits(const CandidateSums& s, const std::vector<int>& runs, const NullCalibration& m0) {
  std::array<Choice, 2> out;
  for (std::size_t h = 0; h < 2; ++h) {
    std::vector<int> train;
    for (std::size_t r = h; r < runs.size(); r += 2) train.push_back(runs[r]);
    out[h] = choose(s, train, m0);
  }
  return out;
}

std::array<Choice, 2> half_fits(const CandidateSums& s, std::size_t n, const NullCalibration& m0) {
  return half_fits(s, all_runs(n), m0);
}

int null_file_count(const runs::PreparedRuns& p, const ModelNull& null, const DiagnosisOptions& options) {
  return std::min(options.null_shrink_files, static_cast<int>(null.runs.size() / std::max<std::size_t>(p.runs.size(), 1)));
}

runs::PreparedRuns null_file(const runs::PreparedRuns& p, const ModelNull& null, int f) {
  const auto n = static_cast<std::ptrdiff_t>(p.runs.size());
  runs::PreparedRuns q = p;
  q.runs.assign(null.runs.begin() + f * n, null.runs.begin() + (f + 1) * n);
  q.layout_of.assign(null.layout_of.begin() + f * n, null.layout_of.begin() + (f + 1) * n);
  return q;
}

namespace {

/// Null files of the records' size (consecutive runs of the null
/// calibration in the records' layouts) and G on each before any candidate.
struct NullFiles {
  runs::PreparedRuns runs;              ///< every file's runs, one after another
  std::vector<std::vector<int>> files;  ///< each file's runs in `runs`
  std::vector<double> before;
};

NullFiles null_files(const runs::PreparedRuns& p, const ModelNull& null, const NullCalibration& m0, int files) {
  const std::size_t n = p.runs.size();
  NullFiles out{p, {}, {}};
  out.runs.runs.assign(null.runs.begin(), null.runs.begin() + static_cast<std::ptrdiff_t>(files * n));
  out.runs.layout_of.assign(null.layout_of.begin(), null.layout_of.begin() + static_cast<std::ptrdiff_t>(files * n));
  for (int f = 0; f < files; ++f) {
    out.files.push_back(run_range(static_cast<std::size_t>(f) * n, n));
    out.before.push_back(gap_value(null.set, out.files.back(), m0));
  }
  return out;
}

/// The candidate's held-out shrink on each null file, split and fitted as
/// the records are; the median over the files.
double median_null_shrink(CandidateSums sums, const NullFiles& null, std::size_t n, const NullCalibration& m0) {
  std::vector<std::array<Choice, 2>> halves;
  std::vector<int> chosen;
  for (const std::vector<int>& runs : null.files) {
    halves.push_back(half_fits(sums, runs, m0));
    chosen.insert(chosen.end(), {halves.back()[0].grid, halves.back()[1].grid});
  }
  keep_keyed_at(sums, std::move(chosen));  // every file's points at once: they share their evaluation
  std::vector<double> shrink;
  for (std::size_t f = 0; f < null.files.size(); ++f) {
    const RunSet held = heldout_set(halves[f], sums, null.files[f]);
    const double b = null.before[f];
    shrink.push_back(b > 0 ? 1.0 - gap_value(held, all_runs(n), m0) / b : 0.0);
  }
  return quantile(shrink, 0.5);
}

}  // namespace

RankedCandidates rank_candidates(const runs::PreparedRuns& p, const std::vector<std::vector<runs::Extension>>& selected,
                                 const std::vector<std::string>& exclude, const ModelNull& null,
                                 const DiagnosisOptions& options, std::string_view stage, bool with_null_shrinks) {
  const auto& registry = candidates_of(options);
  const NullCalibration& m0 = null.calibration;
  const std::size_t n = p.runs.size();
  RankedCandidates out;
  out.null_shrink.assign(registry.size(), std::numeric_limits<double>::quiet_NaN());
  const int files = with_null_shrinks ? null_file_count(p, null, options) : 0;
  // The null files are evaluated with the records: the same layouts, so each
  // grid point's models (the cost) are built once for both; each keeps its
  // own search, fits and held-out sets. Only before any effect is selected,
  // as the null files carry none.
  INSMC_ASSERT(files == 0 || std::all_of(selected.begin(), selected.end(), [](const auto& e) { return e.empty(); }),
               "null shrinks are measured before any effect is selected");
  const NullFiles reference = files > 0 ? null_files(p, null, m0, files) : NullFiles{};
  std::vector<Scored> scored(registry.size());
  std::vector<char> used(registry.size(), 0);  // written from the threads: a byte each, not vector<bool>'s bits
  std::atomic<std::uint64_t> done{0};
  tbb::parallel_for(std::size_t{0}, registry.size(), [&](std::size_t c) {
    if (std::find(exclude.begin(), exclude.end(), registry[c].name) != exclude.end()) return;
    if (files > 0) {
      const runs::PreparedRuns* parts[] = {&p, &reference.runs};
      std::vector<CandidateSums> sums = evaluate_candidate(parts, registry[c], selected, m0, {{}, reference.files});
      out.null_shrink[c] = median_null_shrink(std::move(sums[1]), reference, n, m0);
      scored[c] = score(registry[c], std::move(sums[0]), n, m0, options.seed, p.site);
    } else {
      scored[c] = score(registry[c], evaluate_candidate(p, registry[c], selected, m0), n, m0, options.seed, p.site);
    }
    scored[c].candidate = static_cast<int>(c);
    used[c] = 1;
    report_progress(options, stage, ++done, registry.size() - exclude.size(), "candidates");
  });
  for (std::size_t c = 0; c < registry.size(); ++c)
    if (used[c]) out.ranked.push_back(std::move(scored[c]));
  std::stable_sort(out.ranked.begin(), out.ranked.end(),
                   [](const Scored& a, const Scored& b) { return a.heldout_gap < b.heldout_gap; });
  return out;
}

FirstRanking first_ranking(const RankedCandidates& candidates, const runs::PreparedRuns& p, const ModelNull& null,
                           const DiagnosisOptions& options, double before) {
  const std::vector<Scored>& ranked = candidates.ranked;
  const auto& registry = candidates_of(options);
  const int n = static_cast<int>(p.runs.size());
  FirstRanking d;
  for (const Scored& s : ranked) {
    const Candidate& c = registry[static_cast<std::size_t>(s.candidate)];
    d.ranking.push_back({c.name, c.description, s.parameters, s.heldout_gap, 1.0 - s.heldout_gap / before,
                         std::numeric_limits<double>::quiet_NaN(),
                         log_ratios(pool(s.heldout, all_runs(p.runs.size())), null.calibration),
                         {}, {}, {}});
    EffectArgument a = effect_argument(d.ranking.back(), p.site);
    d.ranking.back().as_effect = std::move(a.text);
    d.ranking.back().as_effect_kept = std::move(a.kept);
  }
  d.top = d.ranking.front().effect;
  for (std::size_t i = 0; i < ranked.size(); ++i)
    d.ranking[i].null_shrink = candidates.null_shrink[static_cast<std::size_t>(ranked[i].candidate)];
  std::vector<std::string> effects;
  for (const CandidateResult& r : d.ranking) effects.push_back(r.effect);
  LikelihoodRanking likelihood = rank_by_likelihood(ranked, effects, p, null, options);
  for (std::size_t i = 0; i < likelihood.candidates.size(); ++i) d.ranking[i].likelihood = std::move(likelihood.candidates[i]);
  d.pairs = std::move(likelihood.pairs);
  if (ranked.size() > 1) {
    // Each candidate's margin behind the first and its resampling standard
    // error (the same resampled runs for all).
    constexpr int kResamples = 500;
    std::vector<std::vector<double>> margins(ranked.size());
    for (int b = 0; b < kResamples; ++b) {
      const std::vector<int> idx = resample(options.seed, 2'000'000 + static_cast<std::uint64_t>(b), n, n);
      const double first = gap_value(ranked[0].heldout, idx, null.calibration);
      for (std::size_t i = 1; i < ranked.size(); ++i)
        margins[i].push_back(gap_value(ranked[i].heldout, idx, null.calibration) - first);
    }
    for (std::size_t i = 1; i < ranked.size(); ++i) {
      const double mean = std::accumulate(margins[i].begin(), margins[i].end(), 0.0) / kResamples;
      double var = 0;
      for (double m : margins[i]) var += (m - mean) * (m - mean);
      d.ranking[i].behind_first_se = std::sqrt(var / (kResamples - 1));
    }
    d.runner_up_margin = ranked[1].heldout_gap - ranked[0].heldout_gap;
    d.runner_up_margin_se = d.ranking[1].behind_first_se;
    const bool single = d.ranking[0].effect.find('|') == std::string::npos &&
                        d.ranking[1].effect.find('|') == std::string::npos;
    if (single && d.runner_up_margin < 2.0 * d.runner_up_margin_se)
      d.top = d.ranking[0].effect + "|" + d.ranking[1].effect;
  }
  return d;
}

}  // namespace insmc::gap
