#include "montecarlo/records/gap/null/null_calibration.h"

#include <tbb/parallel_for.h>

#include <atomic>
#include <fmt/format.h>
#include <optional>

#include "lib/common/assert.h"
#include "lib/common/input_error.h"
#include "montecarlo/records/gap/null/bootstrap.h"
#include "montecarlo/records/runs/simulation/record_simulation.h"
#include "montecarlo/records/runs/prepared_runs.h"

namespace insmc::gap {

std::vector<runs::RunData> simulate_like_records(runs::PreparedRuns& p, const RecordFile& file, const DiagnosisOptions& options,
                                                int runs, std::uint64_t first_run, const std::vector<EffectSpec>& effects,
                                                std::vector<int>& layout_of, const ImportNull* import) {
  TruthOptions truth;
  truth.model = p.site.model;
  truth.system = p.site.system;
  truth.dv_pulse_mps = p.site.dv_pulse_mps;
  truth.filter_interval_s = p.site.filter_interval_s;
  truth.effects = effects;
  const mc::Sampler sampler(options.prior);
  // The runs after the records' scheme, with the estimators the diagnosis uses.
  const TestRunOptions test = runs::record_test_options(p.site);
  const TruthSchemeSetup setup(truth, test, p.site.estimators ? *p.site.estimators : TestRunEstimators{});
  const runs::RecordRunSpec spec{p.site.test_duration_s, p.site.position_resolution_m, p.site.scheme, &setup,
                           p.site.nav_start_s};
  std::vector<runs::RunData> sim(static_cast<std::size_t>(runs));
  std::vector<runs::SchemeEstimates> estimates(static_cast<std::size_t>(runs));
  std::atomic<std::uint64_t> simulated{0};
  const auto total = static_cast<std::uint64_t>(runs);
  const char* stage = !effects.empty() ? "runs with the finding" : import ? "null through the import" : "null calibration";
  tbb::parallel_for(0, runs, [&](int j) {
    report_progress(options, stage, simulated++, total, "truth runs");
    const RecordRun& pattern = file.runs[static_cast<std::size_t>(j) % file.runs.size()];
    const std::uint64_t run = first_run + static_cast<std::uint64_t>(j);
    RecordFile one;
    one.header = file.header;
    one.runs.push_back(simulate_like(pattern, truth, sampler, options.seed, run, spec));
    if (import) add_import_noise(one.runs.front(), file.header, pattern.id, *import, options.seed, run);
    sim[static_cast<std::size_t>(j)] = std::move(runs::extract_runs(one, p.site, options.extraction).front());
    if (p.site.estimators) {
      const std::optional<runs::SchemeEstimates> u = runs::record_estimates(one.runs.front(), p.site, *p.site.estimators);
      INSMC_ASSERT(u.has_value(), "simulated run {} lacks its test grid", j);
      estimates[static_cast<std::size_t>(j)] = *u;
    }
  });
  layout_of.resize(sim.size());
  for (std::size_t j = 0; j < sim.size(); ++j) {
    layout_of[j] = p.place(sim[j]);
    // The run's own estimates, taken off its rows as the records' are.
    if (p.site.estimators) p.take_off_estimates(sim[j], layout_of[j], estimates[j]);
  }
  return sim;
}

void check_null_budget(const runs::PreparedRuns& p, int runs, bool automatic, int nulls) {
  if (p.runs.empty()) return;
  double observations = 0;
  for (const runs::RunData& r : p.runs) observations += static_cast<double>(r.values.size());
  const double per_run = nulls * observations / static_cast<double>(p.runs.size());
  const double bytes = static_cast<double>(runs) * per_run * kNullBytesPerObservation;
  if (bytes <= kMaxNullBytes) return;
  const auto fits = static_cast<long long>(kMaxNullBytes / (per_run * kNullBytesPerObservation));
  throw InputError("--calibration-runs", automatic ? fmt::format("0 (automatic: {})", runs) : std::to_string(runs),
                   fmt::format("{} null runs like the records' ({:.0f} observations a run{}) hold about {:.0f} MB until "
                               "the ranking; at most {:.0f} MB: at most {} calibration runs for these records{}",
                               runs, per_run / nulls, nulls > 1 ? ", twice: the model's null and the import's" : "",
                               bytes / 1e6, kMaxNullBytes / 1e6, fits,
                               fits < 50 ? " (fewer than the 50 a calibration needs: diagnose fewer or shorter runs)"
                                         : ""));
}

std::vector<LogRatios> null_file_log_ratios(const RunSet& set, const NullCalibration& calibration,
                                            const DiagnosisOptions& options, int file_runs) {
  std::vector<LogRatios> out(static_cast<std::size_t>(options.bootstrap));
  const int runs = static_cast<int>(set.size());
  tbb::parallel_for(0, options.bootstrap, [&](int b) {
    const Pooled s = pool(set, resample(options.seed, static_cast<std::uint64_t>(b), file_runs, runs));
    out[static_cast<std::size_t>(b)] = log_ratios(s, calibration, CoherentReference::kAtLeastModelScatter);
  });
  return out;
}

ModelNull calibrate(runs::PreparedRuns& p, const RecordFile& file, const DiagnosisOptions& options, int runs,
               std::vector<Eigen::VectorXd>& z, std::vector<int>& layout_of, const ImportNull* import) {
  std::vector<runs::RunData> sim = simulate_like_records(p, file, options, runs, 0, {}, layout_of, import);
  const std::vector<std::optional<runs::RunAnalyser>> analysers = runs::layout_analysers(p, {});
  std::vector<const runs::RunAnalyser*> pointers;
  for (const std::optional<runs::RunAnalyser>& a : analysers) pointers.push_back(&*a);
  const RunSet set = evaluate_runs(sim, layout_of, pointers, p.keys).set(p.keys);
  z.resize(sim.size());
  tbb::parallel_for(std::size_t{0}, sim.size(), [&](std::size_t j) {
    analysers[static_cast<std::size_t>(layout_of[j])]->analyse(run_values(sim[j]), z[j]);
  });
  ModelNull null;
  null.calibration = NullCalibration::from_null(set);
  const int n = static_cast<int>(p.runs.size());
  const auto B = static_cast<std::size_t>(options.bootstrap);
  null.gaps.resize(B);
  null.unmodelled.resize(B);
  null.pessimistic.resize(B);
  null.log_ratios = null_file_log_ratios(set, null.calibration, options, n);
  tbb::parallel_for(0, options.bootstrap, [&](int b) {
    const auto i = static_cast<std::size_t>(b);
    null.gaps[i] = gap_value(null.log_ratios[i]);
    const SignedGap signed_gap = gap::signed_gap(null.log_ratios[i]);
    null.unmodelled[i] = signed_gap.unmodelled;
    null.pessimistic[i] = signed_gap.pessimistic;
  });
  null.set = set;
  null.runs = std::move(sim);
  null.layout_of = layout_of;
  return null;
}

}  // namespace insmc::gap
