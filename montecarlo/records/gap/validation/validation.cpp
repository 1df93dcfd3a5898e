#include "montecarlo/records/gap/validation/validation.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <boost/math/distributions/binomial.hpp>
#include <cmath>
#include <fmt/format.h>
#include <map>
#include <optional>
#include <tbb/parallel_for.h>

#include "lib/truth/effect.h"
#include "lib/units/units.h"
#include "montecarlo/records/runs/simulation/record_simulation.h"
#include "montecarlo/records/gap/validation/writer_conventions.h"
#include "montecarlo/report/csv.h"
#include "montecarlo/report/json.h"
#include "montecarlo/report/markdown.h"
#include "montecarlo/report/plot/matrix_figure.h"

namespace insmc::gap {
namespace {

EffectSpec scaled_effect(EffectKind kind, double magnitude, double model_pulse_mps) {
  EffectSpec spec = default_effect(kind);
  const EffectInfo& info = kind.info();
  for (std::size_t i = 0; i < info.parameters.size(); ++i) {
    switch (info.parameters[i].magnitude) {
      case EffectMagnitude::kFixed: break;
      case EffectMagnitude::kScaled: spec.values_si[i] *= magnitude; break;
      case EffectMagnitude::kExcessOverModelPulse:
        // Magnitude 1 is the default weight, 0 the model's own.
        spec.values_si[i] = model_pulse_mps * (1.0 + magnitude * (spec.values_si[i] / model_pulse_mps - 1.0));
        break;
    }
  }
  return spec;
}

bool names_effect(const std::string& top, const std::string& effect) {
  const std::vector<std::string> members = class_members(top);
  return std::find(members.begin(), members.end(), effect) != members.end();
}

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

bool selected(const ValidationOptions& options, const std::string& effect) {
  return options.effects.empty() ||
         std::find(options.effects.begin(), options.effects.end(), effect) != options.effects.end();
}

/// Effect files' seeds lie above any null file's (at most 10⁴ of them) and
/// depend only on where the file sits in the full study.
std::uint64_t effect_file_seed(std::uint64_t seed, std::size_t effect, std::size_t magnitude, int file) {
  return seed + 100'000 + 10'000 * effect + 100 * magnitude + static_cast<std::uint64_t>(file);
}

}  // namespace

ValidationOptions ValidationOptions::quick_subset() {
  ValidationOptions o;
  o.quick = true;
  o.runs_per_file = 10;
  o.magnitudes = {30.0};
  o.seeds = 1;
  o.null_files = 4;
  return o;
}

RecordFile own_layout_file(const std::vector<EffectSpec>& effects, std::uint64_t seed, int runs) {
  TruthOptions truth;
  truth.effects = effects;
  runs::OwnFileSpec spec;
  spec.runs = runs;
  // The diagnosis is blind: no truth keys.
  return without_truth(runs::simulate_own_file(truth, mc::Sampler(UncertaintyModel{}), seed, spec));
}

RecordFile file_in_conventions(const std::vector<EffectSpec>& effects, std::uint64_t seed, int runs, const WriterConventions& layout) {
  TruthOptions truth;
  truth.effects = effects;
  ForeignRuns spec;
  spec.runs = runs;
  return simulate_foreign_file(truth, mc::Sampler(UncertaintyModel{}), seed, spec, layout);
}

void validate(const ValidationOptions& options) {
  if (options.null_files < 0 || options.null_files > 10000)
    throw InputError("--null-files", std::to_string(options.null_files), "must lie in [0, 10000]");
  if (options.seeds < 1 || options.seeds > 100) throw InputError("--seeds", std::to_string(options.seeds), "must lie in [1, 100]");
  if (options.runs_per_file < 2 || options.runs_per_file > static_cast<int>(kMaxDiagnosedRuns))
    throw InputError("runs per file", std::to_string(options.runs_per_file),
                     fmt::format("must lie in [2, {}]", kMaxDiagnosedRuns));
  for (const double m : options.magnitudes)
    if (!(m > 0) || m > 1000)
      throw InputError("--magnitudes", fmt::format("{}", fmt::join(options.magnitudes, ",")),
                       "must be a comma list of factors in (0, 1000]");
  for (const std::string& name : options.effects) parse_effect_kind(name, "--effect");
}

ValidationResult validate_diagnosis(const ValidationOptions& options) {
  validate(options);
  ValidationResult result;
  DiagnosisOptions d;
  d.alpha = options.alpha;
  d.max_selected = 1;
  d.null_shrink_files = 0;  // the study scores the shrink itself; the reference is for people reading a report
  d.likelihood_candidates = 0;  // the study scores the ranking by held-out G; the likelihood side is for reports
  // Only a significant file is scored by its ranking (identified, shrink,
  // fitted / true): a file without a gap is not ranked.
  d.rank = RankWhen::kIfSignificant;
  const double model_pulse = TruthOptions{}.dv_pulse_mps;
  // Every file of the study, in report order: null data (the model itself,
  // with its pulses), then each effect by magnitude and seed. A file's data
  // depend only on its place, so the files are diagnosed in parallel.
  struct Job {
    std::string effect = "none";
    std::optional<EffectSpec> spec;
    double magnitude = 0.0;
    int seed = 0;
    std::uint64_t file_seed = 0;
  };
  std::vector<Job> jobs;
  for (int i = 0; i < options.null_files; ++i)
    jobs.push_back({"none", std::nullopt, 0.0, i, options.seed + static_cast<std::uint64_t>(i)});
  const auto& registry = effect_registry();
  for (std::size_t e = 0; e < registry.size(); ++e) {
    const std::string name(registry[e].name);
    if (!selected(options, name)) continue;
    for (std::size_t mi = 0; mi < options.magnitudes.size(); ++mi)
      for (int s = 0; s < options.seeds; ++s)
        jobs.push_back({name, scaled_effect(EffectKind(static_cast<int>(e)), options.magnitudes[mi], model_pulse),
                        options.magnitudes[mi], s, effect_file_seed(options.seed, e, mi, s)});
  }
  // A magnitude that takes an effect beyond its physical range is refused
  // before any file is simulated.
  for (const Job& job : jobs)
    if (job.spec) validate_effect(*job.spec, fmt::format("--magnitudes {:g} x", job.magnitude));
  result.cases.resize(jobs.size());
  std::atomic<std::uint64_t> diagnosed{0};
  tbb::parallel_for(std::size_t{0}, jobs.size(), [&](std::size_t j) {
    const Job& job = jobs[j];
    std::vector<EffectSpec> effects;
    if (job.spec) effects.push_back(*job.spec);
    std::optional<WriterConventions> conventions;
    const bool needs_pulses = job.spec && job.spec->kind.info().needs_pulses;
    if (options.writer == RecordWriter::kForeign) conventions = foreign_conventions_of(job.file_seed, needs_pulses);
    if (options.writer == RecordWriter::kFuzzed) conventions = fuzzed_conventions_of(job.file_seed, needs_pulses, ForeignRuns{}.test_duration_s);
    const RecordFile records = conventions ? file_in_conventions(effects, job.file_seed, options.runs_per_file, *conventions)
                                      : own_layout_file(effects, job.file_seed, options.runs_per_file);
    const auto start = std::chrono::steady_clock::now();
    const Diagnosis g = diagnose(records, d);
    ValidationCase c{job.effect, job.magnitude, job.seed, g.significant, g.first.top, false, 0.0, 0.0, g.gap, g.p_value, 0.0, ""};
    c.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (conventions) c.conventions = conventions->describe();
    if (!job.spec) {
      c.top = g.significant ? g.first.top : "";
      c.identified = !g.significant;
    } else {
      c.identified = g.significant && names_effect(g.first.top, job.effect);
      if (g.significant && !g.first.ranking.empty()) c.shrink = g.first.ranking.front().shrink;
      const EffectInfo& info = effect_info(job.spec->kind);
      for (const CandidateResult& r : g.first.ranking) {
        if (r.effect != job.effect) continue;
        for (const ParameterEstimate& p : r.parameters)
          for (std::size_t i = 0; i < info.parameters.size(); ++i)
            if (info.parameters[i].name == p.name && job.spec->values_si[i] != 0)
              c.recovered_ratio = p.value / job.spec->values_si[i];
      }
    }
    result.cases[j] = c;
    if (options.progress) options.progress("gap-validate", ++diagnosed, jobs.size(), "files");
  });
  std::vector<double> seconds;
  for (const ValidationCase& c : result.cases) seconds.push_back(c.seconds);
  if (!seconds.empty()) {
    result.median_seconds = median(seconds);
    result.max_seconds = *std::max_element(seconds.begin(), seconds.end());
  }
  for (const ValidationCase& c : result.cases) {
    if (c.effect != "none") continue;
    result.null_files++;
    result.false_alarms += c.significant;
  }
  std::vector<double> all_shrinks;
  for (const EffectInfo& info : effect_registry()) {
    if (!selected(options, std::string(info.name))) continue;
    EffectScore sc;
    sc.effect = std::string(info.name);
    std::vector<double> shrinks, ratios;
    struct Tally {
      int files = 0, significant = 0, identified = 0;
    };
    std::map<double, Tally> by_magnitude;
    for (const ValidationCase& c : result.cases) {
      if (c.effect != sc.effect) continue;
      Tally& t = by_magnitude[c.magnitude];
      t.files++;
      t.significant += c.significant;
      t.identified += c.identified;
      if (c.recovered_ratio > 0) ratios.push_back(c.recovered_ratio);
      sc.significant_cases += c.significant;
      sc.identified_anywhere += c.identified;
    }
    for (const auto& [m, t] : by_magnitude) {
      if (2 * t.significant <= t.files) continue;  // not detectable at this magnitude
      sc.detectable_magnitudes.push_back(m);
      sc.detected += t.significant;
      sc.identified += t.identified;
      for (const ValidationCase& c : result.cases)
        if (c.effect == sc.effect && c.magnitude == m && c.significant) shrinks.push_back(c.shrink), all_shrinks.push_back(c.shrink);
    }
    sc.identification_rate = sc.detected ? static_cast<double>(sc.identified) / sc.detected : 0.0;
    sc.median_shrink = median(shrinks);
    sc.median_recovered_ratio = median(ratios);
    for (const auto& [m, t] : by_magnitude)
      if (t.identified >= 0.9 * t.files) { sc.detection_threshold = m; break; }
    // An effect that no magnitude makes detectable has no file the targets
    // apply to: reported as such (validation.md), not scored.
    if (sc.detected == 0) result.undetectable.push_back(sc.effect);
    if (sc.detected > 0 && sc.identification_rate < 0.95)
      result.failures.push_back(fmt::format("{}: top-1 identification {}/{} ({:.0f} %) < 95 % where detectable",
                                            sc.effect, sc.identified, sc.detected, 100 * sc.identification_rate));
    result.scores.push_back(sc);
  }
  result.median_shrink = median(all_shrinks);
  if (result.median_shrink < 0.8)
    result.failures.push_back(fmt::format("median held-out shrink {:.2f} < 0.80", result.median_shrink));
  if (result.null_files > 0) {
    // A rate of exactly alpha still gives more than alpha·n false alarms in
    // a finite set of null files about half the time: the target fails when
    // the count is improbable under alpha (one-sided binomial test at 1 %).
    const boost::math::binomial_distribution<double> at_alpha(result.null_files, options.alpha);
    result.false_alarm_p = result.false_alarms == 0
                               ? 1.0
                               : boost::math::cdf(boost::math::complement(at_alpha, result.false_alarms - 1));
    using B = boost::math::binomial_distribution<double>;
    result.false_alarm_low =
        B::find_lower_bound_on_p(result.null_files, result.false_alarms, 0.025, B::clopper_pearson_exact_interval);
    result.false_alarm_high =
        B::find_upper_bound_on_p(result.null_files, result.false_alarms, 0.025, B::clopper_pearson_exact_interval);
    if (result.false_alarm_p < 0.01)
      result.failures.push_back(fmt::format("false alarms on null data {}/{} are too many for alpha = {} (binomial "
                                            "p = {:.2g})", result.false_alarms, result.null_files, options.alpha,
                                            result.false_alarm_p));
  }
  return result;
}

namespace {

Confusion confusion_of(const ValidationResult& r) {
  Confusion m;
  std::map<std::string, std::map<std::string, int>> counts;
  for (const ValidationCase& c : r.cases) {
    const std::string top = c.significant ? (c.top.empty() ? "(not ranked)" : c.top) : "no gap";
    if (std::find(m.columns.begin(), m.columns.end(), top) == m.columns.end()) m.columns.push_back(top);
    counts[c.effect][top]++;
  }
  m.rows = {"none"};
  for (const EffectInfo& info : effect_registry()) m.rows.emplace_back(info.name);
  for (const std::string& row : m.rows) {
    m.counts.emplace_back();
    for (const std::string& col : m.columns) m.counts.back().push_back(counts[row][col]);
  }
  return m;
}

}  // namespace

mc::Report validation_report(const ValidationResult& r, const ValidationOptions& options) {
  // Confusion: true effect (rows) × reported top (columns).
  const Confusion m = confusion_of(r);
  std::vector<std::string> header = {"true effect"};
  header.insert(header.end(), m.columns.begin(), m.columns.end());
  mc::Table confusion(header);
  for (std::size_t row = 0; row < m.rows.size(); ++row) {
    std::vector<std::string> cells = {m.rows[row]};
    for (const int n : m.counts[row]) cells.push_back(std::to_string(n));
    confusion.add_row(cells);
  }
  mc::Table scores({"effect", "detectable at (x default)", "detected files", "identified", "rate", "median shrink",
                "strict: identified / significant files", "detection threshold (x default)", "median fitted/true"});
  for (const EffectScore& s : r.scores)
    scores.add_row({s.effect, s.detectable_magnitudes.empty() ? "-" : fmt::format("{}", fmt::join(s.detectable_magnitudes, ", ")),
                    std::to_string(s.detected), std::to_string(s.identified),
                    fmt::format("{:.0f} %", 100 * s.identification_rate), fmt::format("{:.2f}", s.median_shrink),
                    fmt::format("{}/{}", s.identified_anywhere, s.significant_cases),
                    s.detection_threshold > 0 ? fmt::format("{}", s.detection_threshold) : "not reached",
                    s.median_recovered_ratio > 0 ? fmt::format("{:.2f}", s.median_recovered_ratio) : "-"});
  // No time per file here: a file's row is the same in any subset of the
  // study (tests/cli/gap_validate_test.cpp), its time is not.
  std::vector<std::string> case_columns = {"effect", "magnitude", "seed", "G", "p", "top", "identified", "shrink"};
  if (options.other_writer()) case_columns.push_back("layout");
  mc::Table cases(case_columns);
  for (const ValidationCase& c : r.cases) {
    std::vector<std::string> row = {c.effect, fmt::format("{}", c.magnitude), std::to_string(c.seed),
                                    fmt::format("{:.3g}", c.gap), fmt::format("{:.3g}", c.p_value), c.top,
                                    c.identified ? "yes" : "no", fmt::format("{:.2f}", c.shrink)};
    if (options.other_writer()) row.push_back(c.conventions);
    cases.add_row(row);
  }
  std::string md = fmt::format(
      "# Gap diagnosis validation on withheld effects{}\n\n"
      "Records from the truth simulator ({} runs per file, system 1, 45°, 15 min test + 90 min), one effect at a "
      "time at magnitudes {} × its defaults (`insmc effects`), {} file(s) each; the diagnosis sees the records "
      "without their `truth.` keys.{}\n\n"
      "Null data (the model itself{}): {} false alarm(s) in {} files (alpha = {}; rate 95 % "
      "interval {:.2g}–{:.2g}, binomial p of so many at alpha {:.2g}).\n\n"
      "Median held-out shrink over the detected files (significant files at magnitudes where the effect is detectable: more "
      "than half of that magnitude's files significant): {:.2f}.\n\nDiagnosis time per file (wall, null calibration "
      "included; the study diagnoses files side by side on every core): median {:.1f} s, max {:.1f} s.\n\n## Per effect\n\n{}\n## Confusion "
      "(rows: true effect; columns: the diagnosis' top effect or class)\n\n{}\n## Every file\n\n{}\n## Targets\n\n",
      options.quick ? " (quick subset)" : "", options.runs_per_file, fmt::join(options.magnitudes, ", "), options.seeds,
      options.writer == RecordWriter::kForeign
          ? " Each file is written in another recorder's conventions (`--layout foreign`, docs/gap-method.md §5): f and r "
            "on grids of their own (column `layout`), a third of the runs stopping 60-80 min into the navigation, "
            "run numbers not consecutive, unknown header keys, no pulse-weight or filter-interval key."
          : options.writer == RecordWriter::kFuzzed
          ? " Each file is written in conventions drawn at random (`--layout fuzzed`, docs/gap-method.md §5): f and r "
            "every 1-60 s, each run's own dropouts up to 10 %, f after the test or not, r resolution 0.1 mm to 3 ft, "
            "short runs, optional header keys given or not (column `layout`)."
          : "",
      options.other_writer() ? ", its f continuous or in 0.1 ft/s pulses as the layout says" : ", with its 0.1 ft/s pulses",
      r.false_alarms, r.null_files, options.alpha, r.false_alarm_low, r.false_alarm_high, r.false_alarm_p, r.median_shrink, r.median_seconds, r.max_seconds, mc::render_markdown(scores), mc::render_markdown(confusion),
      mc::render_markdown(cases));
  for (const std::string& e : r.undetectable)
    md += fmt::format("- {}: not detectable at the magnitudes tried ({} x its defaults): no magnitude has more than "
                      "half its files significant, so no target applies to it\n", e, fmt::join(options.magnitudes, ", "));
  if (r.failures.empty()) md += "Every target holds.\n";
  for (const std::string& f : r.failures) md += "- not met: " + f + "\n";
  mc::Json j = mc::Json::object();
  j["quick"] = options.quick;
  j["layout"] = options.writer == RecordWriter::kFuzzed ? "fuzzed" : options.other_writer() ? "foreign" : "own";
  j["null_files"] = r.null_files;
  j["false_alarms"] = r.false_alarms;
  mc::Json ci = mc::Json::array();
  ci.push_back(r.false_alarm_low);
  ci.push_back(r.false_alarm_high);
  j["false_alarm_rate_ci95"] = ci;
  j["false_alarm_binomial_p"] = r.false_alarm_p;
  j["median_shrink"] = r.median_shrink;
  j["diagnosis_seconds_median"] = r.median_seconds;
  j["diagnosis_seconds_max"] = r.max_seconds;
  mc::Json s = mc::Json::array();
  for (const EffectScore& e : r.scores) {
    mc::Json o = mc::Json::object();
    o["effect"] = e.effect;
    mc::Json mags = mc::Json::array();
    for (double m : e.detectable_magnitudes) mags.push_back(m);
    o["detectable_magnitudes"] = mags;
    o["detected_files"] = e.detected;
    o["significant_files"] = e.significant_cases;
    o["identified_anywhere"] = e.identified_anywhere;
    o["identified"] = e.identified;
    o["identification_rate"] = e.identification_rate;
    o["median_shrink"] = e.median_shrink;
    o["detection_threshold"] = e.detection_threshold;
    o["median_recovered_ratio"] = e.median_recovered_ratio;
    s.push_back(o);
  }
  j["effects"] = s;
  mc::Json f = mc::Json::array();
  for (const std::string& x : r.failures) f.push_back(x);
  j["failures"] = f;
  mc::Json u = mc::Json::array();
  for (const std::string& x : r.undetectable) u.push_back(x);
  j["undetectable"] = u;
  mc::MatrixFigure figure{"confusion",
                          fmt::format("gap-validate: the top candidate of each file against the effect it holds ({} files)",
                                      r.cases.size()),
                          "reported top candidate", "true effect", m.rows, m.columns, m.counts};
  mc::Report report(validation_report_outline());
  report.file("validation.md", std::move(md))
      .file("confusion.md", render_markdown(confusion))
      .file("confusion.csv", mc::render_csv(confusion))
      .file("validation.json", j.dump(2) + "\n")
      .figure("confusion", [figure = std::move(figure)] { return mc::render_matrix_figure(figure); })
      .shown_file(mc::ReportFormat::kMarkdown, "validation.md");
  return report;
}

mc::ReportOutline validation_report_outline() {
  return {"gap-validate",
          {"validation.md", "confusion.md", "confusion.csv", "validation.json"},
          {"confusion"},
          {mc::ReportFormat::kMarkdown}};
}

}  // namespace insmc::gap
