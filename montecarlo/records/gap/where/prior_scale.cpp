#include "montecarlo/records/gap/fit/candidate_fit.h"
#include "montecarlo/records/gap/where/prior_scale.h"

#include <cmath>

#include "montecarlo/records/gap/candidates/definitions.h"
#include "montecarlo/records/gap/null/bootstrap.h"

namespace insmc::gap {

PriorScale fit_prior_scale(const runs::PreparedRuns& p, const NullCalibration& m0, double pessimistic_critical,
                           std::uint64_t seed) {
  // 0.01 … 100 in steps of 10^(1/8) ≈ 1.33: half the candidates' step in
  // log, so that the resampled range says something about the data.
  Candidate c = candidates::bounds();
  std::vector<double>& grid = c.parameters.front().grid;
  grid.clear();
  for (int k = -16; k <= 16; ++k) grid.push_back(std::pow(10.0, k / 8.0));
  const std::vector<std::vector<runs::Extension>> none(p.lattices.size());
  CandidateSums sums = evaluate_candidate(p, c, none, m0);
  const std::size_t n = p.runs.size();
  const std::vector<int> runs = all_runs(n);
  const Choice best = choose(sums, runs, m0);

  PriorScale out;
  out.measured = true;
  out.scale = parameter_values(c, best).front();
  out.at_limit = out.scale == grid.front() || out.scale == grid.back();
  constexpr int kResamples = 200;
  std::vector<double> draws;
  for (int b = 0; b < kResamples; ++b) {
    const std::vector<int> r =
        resample(seed, 3'000'000 + static_cast<std::uint64_t>(b), static_cast<int>(n), static_cast<int>(n));
    draws.push_back(parameter_values(c, choose(sums, r, m0)).front());
  }
  out.low = quantile(draws, 0.16);
  out.high = quantile(draws, 0.84);
  // G₋ as the verdict reads it (coherent groups against at least the model's scatter).
  keep_keyed_at(sums, {best.grid});
  const RunSet set = run_set_under(sums, runs, std::vector<Choice>(n, best));
  const LogRatios ratios =
      log_ratios(pool(set, runs), m0, CoherentReference::kAtLeastModelScatter);
  out.pessimistic_after = signed_gap(ratios).pessimistic;
  out.explains = out.pessimistic_after <= pessimistic_critical;
  return out;
}

}  // namespace insmc::gap
