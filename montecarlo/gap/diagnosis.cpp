#include "montecarlo/gap/diagnosis.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <limits>
#include <map>
#include <numeric>
#include <optional>

#include "lib/common/assert.h"
#include "lib/common/input_error.h"
#include "montecarlo/gap/fit/candidate_fit.h"
#include "montecarlo/gap/model/response.h"
#include "montecarlo/gap/model/scheme_rows.h"
#include "montecarlo/gap/null/record_simulation.h"
#include "montecarlo/gap/records/filter_windows.h"
#include "montecarlo/gap/records/site_values.h"
#include "montecarlo/gap/where/where.h"
#include "montecarlo/random/philox.h"

namespace insmc::mc {
namespace {

using Prepared = PreparedRuns;

/// Every run under base + extensions (built per layout by `build`).
template <class Build>
Evaluated evaluate_under(const Prepared& p, const Build& build, std::vector<std::optional<gap::RunAnalyser>>& analysers) {
  analysers.assign(p.layouts.size(), std::nullopt);
  std::vector<const gap::RunAnalyser*> pointers(p.layouts.size(), nullptr);
  for (std::size_t L = 0; L < p.layouts.size(); ++L) {
    analysers[L].emplace(p.layouts[L], gap::combine(p.bases[L], build(static_cast<int>(L))));
    pointers[L] = &*analysers[L];
  }
  return evaluate_runs(p.runs, p.layout_of, pointers, p.keys);
}

std::vector<int> all_runs(std::size_t n) {
  std::vector<int> v(n);
  for (std::size_t i = 0; i < n; ++i) v[i] = static_cast<int>(i);
  return v;
}

/// Indices of a resample with replacement of `n` out of `pool` (stream index b).
std::vector<int> resample(std::uint64_t seed, std::uint64_t b, int n, int pool) {
  CounterStream s(seed, Stream::Bootstrap, b);
  std::vector<int> idx(static_cast<std::size_t>(n));
  for (int& i : idx) i = std::min(pool - 1, static_cast<int>(s.uniform01() * pool));
  return idx;
}

double quantile(std::vector<double> v, double q) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const double pos = q * static_cast<double>(v.size() - 1);
  const auto i = static_cast<std::size_t>(pos);
  const double w = pos - static_cast<double>(i);
  return i + 1 < v.size() ? (1 - w) * v[i] + w * v[i + 1] : v[i];
}

/// Everything the candidate search needs from the null calibration.
struct Null {
  gap::NullCalibration calibration;        // κ_g, λ_c
  std::vector<double> gaps;                // G of the null files
  std::vector<double> unmodelled;          // G₊ of the null files
  std::vector<double> pessimistic;         // G₋ of the null files
  std::vector<gap::LogRatios> log_ratios;  // ℓ of the null files
  gap::RunSet set;                         // the null runs under the base model
  std::vector<gap::RunData> runs;          // the null runs (estimates taken off)
  std::vector<int> layout_of;              // their layouts
};

double p_value_of(double observed, const std::vector<double>& null) {
  const auto above = std::count_if(null.begin(), null.end(), [&](double g) { return g >= observed; });
  return (1.0 + static_cast<double>(above)) / (1.0 + static_cast<double>(null.size()));
}

struct Scored {
  int candidate = 0;
  double heldout_gap = 0;
  gap::RunSet heldout;  // every run at the other half's fit
  Choice full_fit;
  std::vector<ParameterEstimate> parameters;
};

/// Every run under the other half's fit (runs alternate between the halves
/// in file order): 2-fold cross-validation.
gap::RunSet heldout_set(const CandidateSums& s, std::size_t n, const gap::NullCalibration& m0) {
  std::vector<Choice> heldout_choice(n);
  for (int fold = 0; fold < 2; ++fold) {
    std::vector<int> train, test;
    for (std::size_t r = 0; r < n; ++r) (static_cast<int>(r % 2) == fold ? test : train).push_back(static_cast<int>(r));
    const Choice k = choose(s, train, m0);
    for (int r : test) heldout_choice[static_cast<std::size_t>(r)] = k;
  }
  return run_set_under(s, all_runs(n), heldout_choice);
}

/// 2-fold cross-validation (runs alternate between the halves in file order),
/// the full-data fit and its resampled 16–84 % range.
Scored score(const gap::Candidate& c, const CandidateSums& s, std::size_t n, const gap::NullCalibration& m0,
             std::uint64_t seed) {
  Scored out;
  out.heldout = heldout_set(s, n, m0);
  out.heldout_gap = gap::gap_value(out.heldout, all_runs(n), m0);
  out.full_fit = choose(s, all_runs(n), m0);
  const std::vector<double> best = parameter_values(c, out.full_fit);
  constexpr int kResamples = 200;
  std::vector<std::vector<double>> draws(c.parameters.size());
  for (int b = 0; b < kResamples; ++b) {
    const std::vector<int> runs = resample(seed, 1'000'000 + static_cast<std::uint64_t>(b), static_cast<int>(n), static_cast<int>(n));
    const std::vector<double> theta = parameter_values(c, choose(s, runs, m0));
    for (std::size_t i = 0; i < theta.size(); ++i) draws[i].push_back(theta[i]);
  }
  for (std::size_t i = 0; i < c.parameters.size(); ++i) {
    const gap::CandidateParameter& par = c.parameters[i];
    ParameterEstimate e{par.name, par.dimension, best[i], quantile(draws[i], 0.16), quantile(draws[i], 0.84),
                        par.amplitude ? std::abs(best[i]) >= par.grid.front()
                                      : par.grid.size() > 1 && (best[i] == par.grid.front() || best[i] == par.grid.back())};
    out.parameters.push_back(e);
  }
  return out;
}

std::vector<Scored> rank_candidates(const Prepared& p, const std::vector<std::vector<gap::Extension>>& selected,
                                    const std::vector<std::string>& exclude, const gap::NullCalibration& m0,
                                    std::uint64_t seed) {
  const auto& registry = gap::candidate_registry();
  std::vector<Scored> scored(registry.size());
  std::vector<bool> used(registry.size(), false);
  tbb::parallel_for(std::size_t{0}, registry.size(), [&](std::size_t c) {
    if (std::find(exclude.begin(), exclude.end(), registry[c].name) != exclude.end()) return;
    scored[c] = score(registry[c], evaluate_candidate(p, registry[c], selected, m0), p.runs.size(), m0, seed);
    scored[c].candidate = static_cast<int>(c);
    used[c] = true;
  });
  std::vector<Scored> out;
  for (std::size_t c = 0; c < registry.size(); ++c)
    if (used[c]) out.push_back(std::move(scored[c]));
  std::stable_sort(out.begin(), out.end(), [](const Scored& a, const Scored& b) { return a.heldout_gap < b.heldout_gap; });
  return out;
}

/// The records as the diagnosis uses them, and its site. After a scheme
/// that uses the test run, each run's estimates are recomputed from its test
/// rows (scheme_rows.h): the test rows kept are the filter grid τ..T the
/// estimates use; when a run lacks part of that grid, the navigation rows
/// cannot be conditioned on the estimates and only the test run (still
/// uncompensated) is diagnosed.
struct Records {
  RecordFile file;
  gap::RecordSite site;
  std::vector<gap::SchemeEstimates> estimates;  // per run, for a scheme that uses the test run
  bool navigation_dropped = false;              // the scheme's estimates could not be recomputed
};

Records records_for_diagnosis(const RecordFile& file, const DiagnosisOptions& options,
                              std::vector<std::string>& statements, std::vector<SiteValue>& site_values) {
  Records r{file, {}, {}};
  const RecordHeader header = file.header.without_truth();
  r.site = gap::read_site(header, options.default_pulse_mps);
  // What the header leaves out is inferred from the rows and said: the null
  // is simulated with these values.
  site_values = complete_site(RecordFile{header, file.runs}, r.site, options);
  for (const SiteValue& v : site_values)
    if (v.source != "header") statements.push_back(v.reason);
  r.file.header.set(std::string(kKeyDvPulseMps), r.site.dv_pulse_mps);
  r.file.header.set(std::string(kKeyPositionResolutionM), r.site.position_resolution_m);
  // After a scheme that uses the test run, the windows stay as recorded:
  // its estimates came from them, and an estimator of longer windows can
  // differ by a window's counting noise (5.3's Δf̂(T)).
  if (uses_test_run(r.site.scheme) && r.site.filter_interval_s < options.min_filter_interval_s)
    statements.push_back(fmt::format(
        "f is recorded over {:g} s windows and kept so: scheme {}'s estimates were made from them (the diagnosis "
        "takes longer than with windows of {:g} s or more)",
        r.site.filter_interval_s, to_string(r.site.scheme), options.min_filter_interval_s));
  const gap::FilterWindows windows =
      uses_test_run(r.site.scheme) ? gap::FilterWindows{r.site.filter_interval_s, 1, 0}
                                   : gap::coarsen_filter_windows(r.file, r.site.filter_interval_s,
                                                                 r.site.test_duration_s, options.min_filter_interval_s);
  if (windows.factor > 1) {
    statements.push_back(fmt::format(
        "f is recorded over {:g} s windows: they are summed {} at a time into {:g} s windows (what a {:g} s filter "
        "box counts; nothing the model looks for lies above {:g} Hz){}",
        r.site.filter_interval_s, windows.factor, windows.tau_s, windows.tau_s, 0.5 / windows.tau_s,
        windows.dropped > 0 ? fmt::format("; {} f values in blocks with a gap are left out", windows.dropped) : ""));
    r.site.filter_interval_s = windows.tau_s;
    r.file.header.set("filter_interval_s", windows.tau_s);
  }
  const Scheme scheme = r.site.scheme;
  if (!uses_test_run(scheme)) return r;
  const TestRunOptions test = gap::record_test_options(r.site);
  try {
    validate(test);
  } catch (const InputError& e) {
    // The values come from the records' header, not from an option of gap:
    // name the header key the test-run setting was read from.
    std::string key = e.field();
    for (const auto& [option, header_key] :
         {std::pair{"--test-duration", "test_duration_s"}, std::pair{"--filter-interval", "filter_interval_s"},
          std::pair{"--dv-pulse", "dv_pulse_mps"}, std::pair{"--position-resolution", "position_resolution_m"}})
      if (key == option) key = header_key;
    throw InputError(fmt::format("records' header {} (the test run of scheme {})", key, to_string(scheme)),
                     e.value(), e.allowed());
  }
  const Resolvability resolvable = resolvable_terms(r.site.system, r.site.model, test, options.prior);
  r.site.estimators = make_estimators(test, r.site.model, resolvable.u3, resolvable.u4);
  for (const RecordRun& run : file.runs) {
    const std::optional<gap::SchemeEstimates> u = gap::record_estimates(run, r.site, *r.site.estimators);
    if (!u) {
      statements.push_back(fmt::format(
          "run {} lacks part of the test run's filter grid (f and r at every {:g} s up to T = {:g} s), from which "
          "the scheme's estimates are recomputed: the navigation rows after scheme {} cannot be modelled, so only "
          "the test runs are diagnosed", run.id, r.site.filter_interval_s, r.site.test_duration_s, to_string(scheme)));
      for (RecordRun& kept : r.file.runs)
        std::erase_if(kept.rows, [](const RecordRow& row) { return row.phase != Phase::kTest; });
      r.file.header.set(std::string(kKeyScheme), std::string(to_string(Scheme::kNone)));
      r.site.scheme = Scheme::kNone;
      r.site.estimators.reset();
      r.estimates.clear();
      r.navigation_dropped = true;
      return r;
    }
    r.estimates.push_back(*u);
  }
  // The test rows the estimates used, and no others (the null runs are
  // simulated on the same rows).
  const double tau = r.site.filter_interval_s;
  for (RecordRun& run : r.file.runs)
    std::erase_if(run.rows, [&](const RecordRow& row) {
      const double k = row.t_s / tau;
      return row.phase == Phase::kTest && std::abs(k - std::round(k)) > 1e-6;
    });
  return r;
}

/// Takes the scheme's use of a run's own test-run estimates off its rows
/// (scheme_rows.h): exact, whatever moved the estimates.
void take_off_estimates(gap::RunData& run, const gap::BaseModel& base, const gap::SchemeEstimates& estimates) {
  Eigen::Map<Eigen::VectorXd>(run.values.data(), static_cast<Eigen::Index>(run.values.size())) -=
      base.estimate_map * estimates;
}

Prepared prepare(const Records& records, const DiagnosisOptions& options) {
  Prepared p;
  p.site = records.site;
  p.x_var = options.prior.variance();
  p.runs = gap::extract_runs(records.file, p.site, options.extraction);
  for (std::size_t r = 0; r < p.runs.size(); ++r) {
    const int L = p.layout_index(p.runs[r].layout);
    p.layout_of.push_back(L);
    if (!records.estimates.empty())
      take_off_estimates(p.runs[r], p.bases[static_cast<std::size_t>(L)], records.estimates[r]);
  }
  return p;
}

/// The model's own null: truth runs like the records' (their times, f rows,
/// site, pulses), their run set under the base model, the calibration, and
/// the G of 2000 bootstrap files of the records' size. `z` and `layout_of`
/// keep each null run's row values and layout (for the Allan curves).
Null calibrate(Prepared& p, const RecordFile& file, const DiagnosisOptions& options, int runs,
               std::vector<Eigen::VectorXd>& z, std::vector<int>& layout_of) {
  TruthOptions truth;
  truth.model = p.site.model;
  truth.system = p.site.system;
  truth.dv_pulse_mps = p.site.dv_pulse_mps;
  truth.filter_interval_s = p.site.filter_interval_s;
  const Sampler sampler(options.prior);
  // The null after the records' scheme, with the estimators the diagnosis uses.
  const TestRunOptions test = gap::record_test_options(p.site);
  const TruthSchemeSetup setup(truth, test, p.site.estimators ? *p.site.estimators : TestRunEstimators{});
  const RecordRunSpec spec{p.site.test_duration_s, p.site.position_resolution_m, p.site.scheme, &setup,
                           p.site.nav_start_s};
  std::vector<gap::RunData> sim(static_cast<std::size_t>(runs));
  std::vector<gap::SchemeEstimates> estimates(static_cast<std::size_t>(runs));
  tbb::parallel_for(0, runs, [&](int j) {
    const RecordRun& pattern = file.runs[static_cast<std::size_t>(j) % file.runs.size()];
    RecordFile one;
    one.header = file.header;
    one.runs.push_back(simulate_like(pattern, truth, sampler, options.seed, static_cast<std::uint64_t>(j), spec));
    sim[static_cast<std::size_t>(j)] = std::move(gap::extract_runs(one, p.site, options.extraction).front());
    if (p.site.estimators) {
      const std::optional<gap::SchemeEstimates> u = gap::record_estimates(one.runs.front(), p.site, *p.site.estimators);
      INSMC_ASSERT(u.has_value(), "null run {} lacks its test grid", j);
      estimates[static_cast<std::size_t>(j)] = *u;
    }
  });
  layout_of.resize(sim.size());
  for (std::size_t j = 0; j < sim.size(); ++j) {
    layout_of[j] = p.layout_index(sim[j].layout);
    // The null run's own estimates, taken off its rows as the records' are.
    if (p.site.estimators) take_off_estimates(sim[j], p.bases[static_cast<std::size_t>(layout_of[j])], estimates[j]);
  }
  std::vector<gap::RunAnalyser> analysers;
  std::vector<const gap::RunAnalyser*> pointers;
  analysers.reserve(p.layouts.size());
  for (std::size_t L = 0; L < p.layouts.size(); ++L) {
    analysers.emplace_back(p.layouts[L], gap::combine(p.bases[L], {}));
    pointers.push_back(&analysers.back());
  }
  const gap::RunSet set = evaluate_runs(sim, layout_of, pointers, p.keys).set(p.keys);
  z.resize(sim.size());
  tbb::parallel_for(std::size_t{0}, sim.size(), [&](std::size_t j) {
    analysers[static_cast<std::size_t>(layout_of[j])].analyse(run_values(sim[j]), z[j]);
  });
  Null null;
  null.calibration = gap::NullCalibration::from_null(set);
  const int n = static_cast<int>(p.runs.size());
  const auto B = static_cast<std::size_t>(options.bootstrap);
  null.gaps.resize(B);
  null.unmodelled.resize(B);
  null.pessimistic.resize(B);
  null.log_ratios.resize(B);
  tbb::parallel_for(0, options.bootstrap, [&](int b) {
    const auto i = static_cast<std::size_t>(b);
    const gap::Pooled s = gap::pool(set, resample(options.seed, static_cast<std::uint64_t>(b), n, runs));
    null.log_ratios[i] = gap::log_ratios(s, null.calibration);
    null.gaps[i] = gap::gap_value(null.log_ratios[i]);
    const gap::SignedGap signed_gap = gap::signed_gap(null.log_ratios[i]);
    null.unmodelled[i] = signed_gap.unmodelled;
    null.pessimistic[i] = signed_gap.pessimistic;
  });
  null.set = set;
  null.runs = std::move(sim);
  null.layout_of = layout_of;
  return null;
}

/// Each candidate's held-out shrink on `files` null files of the records'
/// size (consecutive runs of the null calibration, split and fitted as the
/// records are), the median over the files: what fitting the candidate
/// gains on noise alone, the reference its shrink on the records is read
/// against. NaN for a candidate excluded.
std::vector<double> null_shrinks(const Prepared& p, const Null& null, int files, const gap::NullCalibration& m0) {
  const auto& registry = gap::candidate_registry();
  const std::size_t n = p.runs.size();
  files = std::min(files, static_cast<int>(null.runs.size() / std::max<std::size_t>(n, 1)));
  std::vector<std::vector<double>> per(registry.size());
  const std::vector<std::vector<gap::Extension>> none(p.layouts.size());
  for (int f = 0; f < files; ++f) {
    Prepared q = p;
    q.runs.assign(null.runs.begin() + static_cast<std::ptrdiff_t>(f * n),
                  null.runs.begin() + static_cast<std::ptrdiff_t>((f + 1) * n));
    q.layout_of.assign(null.layout_of.begin() + static_cast<std::ptrdiff_t>(f * n),
                       null.layout_of.begin() + static_cast<std::ptrdiff_t>((f + 1) * n));
    std::vector<int> idx(n);
    for (std::size_t r = 0; r < n; ++r) idx[r] = static_cast<int>(f * n + r);
    const double before = gap::gap_value(null.set, idx, m0);
    std::vector<double> shrink(registry.size());
    tbb::parallel_for(std::size_t{0}, registry.size(), [&](std::size_t c) {
      const gap::RunSet held = heldout_set(evaluate_candidate(q, registry[c], none, m0), n, m0);
      shrink[c] = before > 0 ? 1.0 - gap::gap_value(held, all_runs(n), m0) / before : 0.0;
    });
    for (std::size_t c = 0; c < registry.size(); ++c) per[c].push_back(shrink[c]);
  }
  std::vector<double> out(registry.size(), std::numeric_limits<double>::quiet_NaN());
  for (std::size_t c = 0; c < registry.size(); ++c)
    if (!per[c].empty()) out[c] = quantile(per[c], 0.5);
  return out;
}

std::string fmt_params(const std::vector<ParameterEstimate>& ps) {
  std::string s;
  for (const ParameterEstimate& e : ps) s += (s.empty() ? "" : ", ") + e.name + "=" + format_quantity(e.value, e.dimension);
  return s;
}

/// What the ranking cannot support, said plainly (issue 7: priors too narrow,
/// effect not identifiable, disturbances masked).
void honest_statements(Diagnosis& d) {
  if (!d.ranked || !d.significant) return;
  const CandidateResult& top = d.ranking.front();
  for (const ParameterEstimate& p : top.parameters)
    if (p.at_grid_edge)
      d.statements.push_back(fmt::format("the top candidate's {} is fitted at the edge of its range ({}): the data lie "
                                         "beyond what this candidate covers, so the ranking shows a direction, not a "
                                         "fitted effect", p.name, format_quantity(p.value, p.dimension)));
  const double left = d.greedy.empty() ? top.heldout_gap_after : d.greedy.back().heldout_gap;
  if (!d.greedy.empty() && d.greedy.back().p_value < d.alpha && left > 3.0 * d.null_gap_critical)
    d.statements.push_back(fmt::format("after {} effect(s) the held-out gap is still G = {:.3g}, over three times the "
                                       "null's critical {:.3g}: no candidate (alone or combined) explains these data; "
                                       "the system lies far outside the model's priors or has disturbances the "
                                       "candidates do not describe", d.greedy.size(), left, d.null_gap_critical));
  for (const CandidateResult& c : d.ranking) {
    if (c.effect != "bounds" || c.parameters.empty()) continue;
    const bool chosen = std::find(d.selected.begin(), d.selected.end(), c.effect) != d.selected.end() ||
                        d.top.find(c.effect) != std::string::npos;
    if (chosen && c.shrink > 0.1)
      d.statements.push_back(fmt::format("priors wider than Table 3.1 by a factor {} (bounds) remove {:.0f} % of the "
                                         "held-out gap: Table 3.1's priors are too narrow for this system",
                                         c.parameters.front().value, 100 * c.shrink));
  }
  // Candidates that change nothing on held-out runs: with these records they
  // are either absent or masked by what is present (not identifiable here).
  std::string traceless;
  for (const CandidateResult& c : d.ranking)
    if (std::abs(c.shrink) < 0.01) traceless += (traceless.empty() ? "" : ", ") + c.effect;
  if (!traceless.empty())
    d.statements.push_back(fmt::format("no held-out trace (|shrink| < 1 %): {}; with these records they are absent "
                                       "or masked by what is present, so the data say nothing about them", traceless));
  if (d.top.find('|') != std::string::npos)
    d.statements.push_back(fmt::format("{} are not told apart by these data (held-out margin {:.3g} ± {:.3g}): "
                                       "reported as one class", d.top, d.runner_up_margin, d.runner_up_margin_se));
}

}  // namespace

Diagnosis diagnose(const RecordFile& file, const DiagnosisOptions& options) {
  Diagnosis d;
  const Records records = records_for_diagnosis(file, options, d.statements, d.site);
  Prepared p = prepare(records, options);
  d.alpha = options.alpha;
  d.runs = static_cast<int>(p.runs.size());
  const int n = d.runs;
  int with_test = 0, with_nav = 0;
  for (const gap::RunData& r : p.runs) {
    with_test += r.layout.test_rows > 0;
    with_nav += static_cast<int>(r.layout.rows.size()) > r.layout.test_rows;
  }
  if (with_test == 0)
    throw InputError("records", "no test rows", "the diagnosis needs the test run (phase test, 0 <= t_s <= T)");
  d.scheme = std::string(to_string(file.header.scheme()));
  if (with_nav < n && !records.navigation_dropped)
    d.statements.push_back(fmt::format("{} of {} runs stop at or before the end of the test: they count only in "
                                       "the test-run groups", n - with_nav, n));

  // Gap against the null of the model itself (its layouts join the key
  // space before any run is placed in it).
  std::vector<Eigen::VectorXd> null_z;
  std::vector<int> null_layout;
  const int ncal = options.calibration_runs > 0 ? options.calibration_runs : std::max(200, 10 * n);
  d.calibration_runs = ncal;
  const Null null = calibrate(p, records.file, options, ncal, null_z, null_layout);
  std::vector<std::optional<gap::RunAnalyser>> analysers;
  const Evaluated base = evaluate_under(p, [](int) { return std::vector<const gap::Extension*>{}; }, analysers);
  const gap::Pooled observed = gap::pool(base.set(p.keys), all_runs(p.runs.size()));
  const gap::LogRatios observed_ratios = gap::log_ratios(observed, null.calibration);
  d.gap = gap::gap_value(observed_ratios);
  // One-sided: an unmodelled effect shows as more scatter or more in common
  // than the model; less is the model being pessimistic, a finding of its own.
  const gap::SignedGap signed_gap = gap::signed_gap(observed_ratios);
  d.unmodelled_gap = signed_gap.unmodelled;
  d.unmodelled_critical = quantile(null.unmodelled, 1.0 - options.alpha);
  d.p_value = p_value_of(d.unmodelled_gap, null.unmodelled);
  d.significant = d.p_value < options.alpha;
  d.null_gap_median = quantile(null.gaps, 0.5);
  d.null_gap_critical = quantile(null.gaps, 1.0 - options.alpha);
  d.pessimistic.value = signed_gap.pessimistic;
  d.pessimistic.critical = quantile(null.pessimistic, 1.0 - options.alpha);
  d.pessimistic.p_value = p_value_of(signed_gap.pessimistic, null.pessimistic);
  d.pessimistic.significant = signed_gap.pessimistic > 0 && d.pessimistic.p_value < options.alpha;
  if (n < 20)
    d.statements.push_back(fmt::format("{} runs: the gap's power is reduced (a null file of {} runs scatters "
                                       "up to G = {:.3g} at alpha = {})", n, n, d.null_gap_critical, options.alpha));

  // Where it lies.
  d.groups = group_results(observed, null.calibration, null.log_ratios, options.alpha);
  if (d.pessimistic.significant) d.pessimistic.where = pessimistic_groups(d.groups, null.log_ratios, options.alpha);
  d.by_kind = shares_by(d.groups, [](const GroupResult& g) {
    return std::string(g.coherent ? "common to all runs" : "run-to-run scatter");
  });
  d.by_axis = shares_by(d.groups, [](const GroupResult& g) {
    const int axis = gap::group_axis(g.representative());
    return axis < 0 ? std::string("estimates") : std::string(1, "xyz"[axis]);
  });
  d.by_stage = shares_by(d.groups, [](const GroupResult& g) { return gap::group_stage(g.representative()); });
  d.by_window = shares_by(d.groups, [](const GroupResult& g) {
    if (g.representative() == gap::kEstimatesGroup) return std::string("estimates");
    return g.coherent && gap::group_stage(g.representative()) != "test-run fit" ? std::string("after test (all windows)")
                                                                               : gap::group_window(g.group);
  });
  {
    std::vector<Eigen::VectorXd> z(p.runs.size());
    std::vector<const gap::Layout*> layouts, null_layouts;
    std::vector<const Eigen::VectorXd*> expected, null_expected;
    for (std::size_t r = 0; r < p.runs.size(); ++r) {
      const gap::RunAnalyser& a = *analysers[static_cast<std::size_t>(p.layout_of[r])];
      a.analyse(run_values(p.runs[r]), z[r]);
      layouts.push_back(&p.layouts[static_cast<std::size_t>(p.layout_of[r])]);
      expected.push_back(&a.expected_square());
    }
    for (std::size_t j = 0; j < null_z.size(); ++j) {
      null_layouts.push_back(&p.layouts[static_cast<std::size_t>(null_layout[j])]);
      null_expected.push_back(&analysers[static_cast<std::size_t>(null_layout[j])]->expected_square());
    }
    d.time_functions = time_function_shares(layouts, z, p.site);
    d.allan = allan_curves(layouts, z, expected, null_layouts, null_z, null_expected, p.site.filter_interval_s);
  }

  // Which effect, and how far the gap shrinks.
  if (n < options.minimum_runs) {
    d.statements.push_back(fmt::format("{} runs: too few to fit candidate effects on one half and score them on "
                                       "the other (at least {} needed); no ranking", n, options.minimum_runs));
    return d;
  }
  if (!d.significant) {
    d.statements.push_back(fmt::format("no significant gap (p = {:.3g} >= alpha = {}): no effect is selected",
                                       d.p_value, options.alpha));
  }
  const auto& registry = gap::candidate_registry();
  std::vector<std::vector<gap::Extension>> selected(p.layouts.size());
  std::vector<std::string> taken;
  d.heldout_gap_before = d.gap;
  double before = d.gap;
  for (int step = 0; step < std::max(1, options.max_selected); ++step) {
    const std::vector<Scored> ranked = rank_candidates(p, selected, taken, null.calibration, options.seed);
    if (ranked.empty()) break;
    if (step == 0) {
      d.ranked = true;
      for (const Scored& s : ranked) {
        const gap::Candidate& c = registry[static_cast<std::size_t>(s.candidate)];
        d.ranking.push_back({c.name, c.description, s.parameters, s.heldout_gap, 1.0 - s.heldout_gap / before,
                             std::numeric_limits<double>::quiet_NaN(),
                             gap::log_ratios(gap::pool(s.heldout, all_runs(p.runs.size())), null.calibration)});
      }
      d.top = d.ranking.front().effect;
      if (options.null_shrink_files > 0) {
        const std::vector<double> reference = null_shrinks(p, null, options.null_shrink_files, null.calibration);
        for (std::size_t i = 0; i < ranked.size(); ++i)
          d.ranking[i].null_shrink = reference[static_cast<std::size_t>(ranked[i].candidate)];
      }
      if (ranked.size() > 1) {
        // Runner-up margin and its resampling standard error.
        constexpr int kResamples = 500;
        std::vector<double> margins;
        for (int b = 0; b < kResamples; ++b) {
          const std::vector<int> idx = resample(options.seed, 2'000'000 + static_cast<std::uint64_t>(b), n, n);
          margins.push_back(gap::gap_value(ranked[1].heldout, idx, null.calibration) -
                            gap::gap_value(ranked[0].heldout, idx, null.calibration));
        }
        d.runner_up_margin = ranked[1].heldout_gap - ranked[0].heldout_gap;
        const double mean = std::accumulate(margins.begin(), margins.end(), 0.0) / kResamples;
        double var = 0;
        for (double m : margins) var += (m - mean) * (m - mean);
        d.runner_up_margin_se = std::sqrt(var / (kResamples - 1));
        const bool single = d.ranking[0].effect.find('|') == std::string::npos &&
                            d.ranking[1].effect.find('|') == std::string::npos;
        if (single && d.runner_up_margin < 2.0 * d.runner_up_margin_se)
          d.top = d.ranking[0].effect + "|" + d.ranking[1].effect;
      }
    }
    if (!d.significant) break;
    const Scored& best = ranked.front();
    const gap::Candidate& c = registry[static_cast<std::size_t>(best.candidate)];
    if (step > 0 && best.heldout_gap >= before) break;  // nothing left that helps on held-out runs
    const double left = gap::signed_gap(gap::log_ratios(gap::pool(best.heldout, all_runs(p.runs.size())),
                                                        null.calibration)).unmodelled;
    GreedyStep g{c.name, best.parameters, best.heldout_gap, p_value_of(left, null.unmodelled)};
    d.greedy.push_back(g);
    d.selected.push_back(step == 0 ? d.top : c.name);
    taken.push_back(c.name);
    const std::vector<double> theta = parameter_values(c, best.full_fit);
    for (std::size_t L = 0; L < p.layouts.size(); ++L) {
      const gap::LayoutContext ctx{&p.layouts[L], &p.site, &p.bases[L], {}};
      selected[L].push_back(c.build(ctx, theta));
    }
    before = best.heldout_gap;
    if (g.p_value >= options.alpha) break;  // no significant gap remains
    if (step + 1 == options.max_selected)
      d.statements.push_back(fmt::format("a significant gap remains after {} effects ({}); the greedy search stops "
                                         "there", step + 1, fmt_params(best.parameters)));
  }
  honest_statements(d);
  return d;
}

RecordFile merge_record_files(const std::vector<RecordFile>& files, const std::vector<std::string>& names) {
  RecordFile out = files.front();
  std::map<std::int64_t, bool> ids;
  for (const RecordRun& r : out.runs) ids[r.id] = true;
  std::int64_t next = ids.empty() ? 0 : ids.rbegin()->first + 1;
  for (std::size_t f = 1; f < files.size(); ++f) {
    const RecordHeader& h = files[f].header;
    const RecordHeader& h0 = files.front().header;
    if (h.latitude_deg() != h0.latitude_deg() || h.system() != h0.system() ||
        h.test_duration_s() != h0.test_duration_s() || h.scheme() != h0.scheme() ||
        h.dv_pulse_mps() != h0.dv_pulse_mps() || h.nav_start_s() != h0.nav_start_s())
      throw InputError("--records " + names[f], "header",
                       "all record files of one diagnosis must share latitude_deg, system, test_duration_s, "
                       "scheme, nav_start_s and dv_pulse_mps with " + names.front());
    for (RecordRun r : files[f].runs) {
      if (ids.count(r.id)) r.id = next;
      for (RecordRow& row : r.rows) row.run = r.id;
      ids[r.id] = true;
      next = std::max(next, r.id + 1);
      out.runs.push_back(std::move(r));
    }
  }
  return out;
}

}  // namespace insmc::mc
