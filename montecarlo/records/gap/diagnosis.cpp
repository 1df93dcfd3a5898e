// The orchestrator: one call per stage, in the order of README.md; each
// stage returns its result, which diagnose() keeps in the Diagnosis.
#include "montecarlo/records/gap/diagnosis.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <memory>
#include <optional>
#include <utility>

#include "lib/common/input_error.h"
#include "lib/truth/simulator.h"
#include "montecarlo/records/gap/candidates/raw_limits.h"
#include "montecarlo/records/gap/fit/candidate_fit.h"
#include "montecarlo/records/gap/null/bootstrap.h"
#include "montecarlo/records/gap/null/import_null.h"
#include "montecarlo/records/gap/null/null_calibration.h"
#include "montecarlo/records/gap/ranking/finding_check.h"
#include "montecarlo/records/gap/ranking/greedy.h"
#include "montecarlo/records/gap/ranking/statements.h"
#include "montecarlo/records/runs/prepared_runs.h"
#include "montecarlo/records/gap/where/locate.h"
#include "montecarlo/records/gap/where/prior_scale.h"
#include "montecarlo/records/gap/where/estimate_test.h"
#include "montecarlo/records/gap/where/outliers.h"
#include "montecarlo/records/gap/where/unread_rows.h"
#include "montecarlo/records/gap/ranking/estimate_naming.h"

namespace insmc::gap {
namespace {

/// Every run under the base model of its layout.
EvaluatedRuns evaluate_under_base(const runs::PreparedRuns& p, std::vector<std::optional<runs::RunAnalyser>>& analysers) {
  analysers = runs::layout_analysers(p, {});
  std::vector<const runs::RunAnalyser*> pointers(p.layouts.size(), nullptr);
  for (std::size_t L = 0; L < p.layouts.size(); ++L) pointers[L] = &*analysers[L];
  return evaluate_runs(p.runs, p.layout_of, pointers, p.keys);
}

/// The raw-sensor stage's verdict, when import-imu left one in the header.
struct RawStage {
  std::vector<std::string> statements;
  double gyro_ratio = 0, accel_ratio = 0;
};
RawStage raw_stage_of(const RecordFile& file, const std::string& top) {
  RawStage out;
  if (const auto raw = runs::raw_stage_from_header(file.header)) {
    out.statements = raw_stage_statements(*raw, top);
    out.gyro_ratio = raw->gyro_ratio;
    out.accel_ratio = raw->accel_ratio;
  }
  return out;
}

/// The per-run estimates against the prior (where/estimate_test.h): tested
/// jointly with G₊ over the same null files, so that the file is
/// significant at alpha by either; when they stand beyond it, the
/// candidates acting inside the priors are scored on them.
/// `rows_p`: the rows' own p-value (G₊ against the null files).
EstimateTest test_run_estimates(const runs::PreparedRuns& p,
                                const std::vector<std::optional<runs::RunAnalyser>>& analysers, const ModelNull& null,
                                const DiagnosisOptions& options, double rows_p) {
  std::vector<const runs::RunAnalyser*> pointers;
  for (const auto& a : analysers) pointers.push_back(&*a);
  const RunEstimates e = run_estimates(p, pointers, null);
  EstimateTest t = test_estimates(e, null, options, rows_p);
  if (t.measured && t.significant) {
    const int L = p.layout_of.front();
    name_from_estimates(t, e, p, *analysers[static_cast<std::size_t>(L)], L,
                        options.candidates ? *options.candidates : candidate_registry());
  }
  return t;
}

/// The estimates name the effect when the rows' scatter does not see it
/// (G₊ alone not significant), or when every member of the ranking's top
/// acts inside the priors too: among effects the same in every run or
/// priors widened, the direction the estimates move in is what tells them
/// apart, and G pools it with the rows over each axis. They do not
/// overrule an effect ranked first that the rows tell apart from theirs,
/// unless what the rows rank first is widened priors (`bounds`, which nests
/// every effect acting inside them); estimates that fit `bounds` best do not
/// narrow a class of the rows holding it and another effect.
struct InsidePriors {
  std::optional<std::string> statement;
  std::optional<std::string> top;  ///< the estimates' name, replacing the ranking's top
};
InsidePriors name_inside_priors(const Diagnosis& d) {
  const EstimateTest& t = d.estimate_test;
  if (!d.ranked() || !t.significant || t.named.empty() || t.named == d.first.top) return {};
  const auto scored = [&](const std::string& name) {
    return std::any_of(t.scores.begin(), t.scores.end(), [&](const EstimateScore& s) { return s.effect == name; });
  };
  const std::vector<std::string> first_members = class_members(d.first.top);
  const bool inside = !d.first.top.empty() && std::all_of(first_members.begin(), first_members.end(), scored);
  const bool rows_see_it = d.p_value < d.alpha;
  if (rows_see_it && !inside) return {};
  const bool first_is_widened_priors =
      std::find(first_members.begin(), first_members.end(), "bounds") != first_members.end();
  if (rows_see_it && first_is_widened_priors && first_members.size() > 1 && t.named == "bounds") {
    // Widened priors nest every effect acting inside them, so estimates that
    // fit them best cannot split a class the rows made of them and another
    // such effect: on the estimates alone the nesting one wins whenever the
    // other's signature fits the truth imperfectly. The rows' class stands.
    return {fmt::format(
                "the test run's estimates stand beyond the prior (least p {:.3g}, over the table {:.3g}) and fit "
                "widened priors best, which nest every effect acting inside them: they do not split the rows' class "
                "{}, which is kept",
                t.min_p, t.family_p, d.first.top),
            std::nullopt};
  }
  if (rows_see_it && !first_is_widened_priors) {
    // The estimates are one group of the rows' G: between effects the rows
    // tell apart (more than twice the resampled margin's standard error,
    // the rule that makes a class of the first two) the rows decide. Where
    // the rows rank widened priors first, they say the unit is beyond the
    // priors and not which effect moved it: there the estimates' direction
    // names it.
    const CandidateResult* closest = nullptr;
    for (const std::string& m : class_members(t.named))
      for (const CandidateResult& c : d.first.ranking)
        if (c.effect == m && (closest == nullptr || c.heldout_gap_after < closest->heldout_gap_after)) closest = &c;
    const CandidateResult& first = d.first.ranking.front();
    if (closest != nullptr && closest != &first && std::isfinite(closest->behind_first_se) &&
        closest->heldout_gap_after - first.heldout_gap_after >= 2.0 * closest->behind_first_se) {
      return {fmt::format(
                  "the test run's estimates stand beyond the prior (least p {:.3g}, over the table {:.3g}) and point "
                  "to {}, but the rows tell {} ahead of it (held-out G {:.3g} against {:.3g}, more than twice the "
                  "margin's resampled standard error {:.2g}): {} is kept",
                  t.min_p, t.family_p, t.named, d.first.top, first.heldout_gap_after, closest->heldout_gap_after,
                  closest->behind_first_se, d.first.top),
              std::nullopt};
    }
  }
  return {fmt::format("the test run's estimates stand beyond the prior (least p {:.3g}, over the table {:.3g}) and "
                      "name {}{} where the ranking by held-out G named {}: {}",
                      t.min_p, t.family_p, t.named, t.told_apart_by.empty() ? "" : " (" + t.told_apart_by + ")",
                      d.first.top,
                      rows_see_it ? "the estimates tell apart effects that act inside the priors"
                                  : "the rows' scatter alone is within the null"),
          t.named};
}

/// The raw stage's statements and ratios added to `d` (the last stage).
Diagnosis with_raw_stage(Diagnosis d, const RecordFile& file) {
  RawStage raw = raw_stage_of(file, d.first.top);
  for (std::string& s : raw.statements) d.statements.push_back(std::move(s));
  d.raw_gyro_ratio = raw.gyro_ratio;
  d.raw_accel_ratio = raw.accel_ratio;
  return d;
}

}  // namespace

Diagnosis diagnose(const RecordFile& file, const DiagnosisOptions& given) {
  validate(given);
  DiagnosisOptions options = given;
  Diagnosis d;
  if (const auto raw = runs::raw_stage_from_header(file.header); raw && !options.candidates)
    options.candidates = std::make_shared<const std::vector<Candidate>>(
        limit_candidates(candidate_registry(), *raw, d.statements));
  if (const auto err = truth_latitude_error(file.header.latitude_deg() * kDegToRad, "header latitude_deg"))
    throw InputError(err->field(), err->value(), "the diagnosis's null is simulated at the site, and " + err->allowed());
  const runs::Records records = runs::read_records(file, options, d.statements, d.site);
  runs::PreparedRuns p = prepare(records, options);
  d.alpha = options.alpha;
  d.runs = static_cast<int>(p.runs.size());
  const int n = d.runs;
  int with_test = 0, with_nav = 0;
  for (const runs::RunData& r : p.runs) {
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
  {
    std::vector<std::string> unused;  // the statements are made below, when the null through the import is built
    check_null_budget(p, ncal, options.calibration_runs == 0, import_null_for(records.file, unused) ? 2 : 1);
  }
  const ModelNull null = calibrate(p, records.file, options, ncal, null_z, null_layout);
  std::vector<std::optional<runs::RunAnalyser>> analysers;
  const EvaluatedRuns base = evaluate_under_base(p, analysers);
  const Pooled observed = pool(base.set(p.keys), all_runs(p.runs.size()));
  const LogRatios observed_ratios =
      log_ratios(observed, null.calibration, CoherentReference::kAtLeastModelScatter);
  d.gap = gap_value(observed_ratios);
  d.outliers = find_outliers(p, analysers, null_z, options.alpha);
  d.unread = screen_unread_rows(records.file, p.runs, records.site.position_resolution_m);
  if (const std::string s = unread_rows_sentence(d.unread); !s.empty()) d.statements.push_back(s);
  // The baseline of the candidates' held-out shrink, read as they are.
  d.heldout_gap_before = gap_value(log_ratios(observed, null.calibration));
  // One-sided: an unmodelled effect shows as more scatter or more in common
  // than the model; less is the model being pessimistic, a finding of its own.
  const SignedGap signed_gap = gap::signed_gap(observed_ratios);
  d.unmodelled_gap = signed_gap.unmodelled;
  d.unmodelled_critical = critical_value(null.unmodelled, options.alpha);
  d.p_value = p_value_of(d.unmodelled_gap, null.unmodelled);
  d.significant = d.p_value < options.alpha;
  d.null_gap_median = quantile(null.gaps, 0.5);
  d.null_gap_critical = critical_value(null.gaps, options.alpha);
  d.pessimistic.value = signed_gap.pessimistic;
  d.pessimistic.critical = critical_value(null.pessimistic, options.alpha);
  d.pessimistic.p_value = p_value_of(signed_gap.pessimistic, null.pessimistic);
  d.pessimistic.significant = signed_gap.pessimistic > 0 && d.pessimistic.p_value < options.alpha;
  if (d.pessimistic.significant)
    d.pessimistic.prior_scale = fit_prior_scale(p, null.calibration, d.pessimistic.critical, options.seed);
  // Records from import-imu with its raw stage: the main verdict is against
  // the null through the import; the model's own stays beside it (the
  // report gives it first) and is what the candidates explain.
  std::optional<OwnNoiseRuns> own_noise;
  if (const std::optional<ImportNull> import = import_null_for(records.file, d.statements)) {
    d.against_model = {true, d.unmodelled_gap, d.unmodelled_critical, d.p_value, d.significant, d.gap,
                       d.null_gap_critical, d.null_gap_median};
    own_noise.emplace();
    const ModelNull through = calibrate(p, records.file, options, ncal, own_noise->z, own_noise->layout_of, &*import);
    own_noise->log_ratios = null_file_log_ratios(through.set, null.calibration, options, n);
    const LogRatios through_ratios =
        log_ratios(observed, through.calibration, CoherentReference::kAtLeastModelScatter);
    d.gap = gap_value(through_ratios);
    d.null_gap_median = quantile(through.gaps, 0.5);
    d.null_gap_critical = critical_value(through.gaps, options.alpha);
    const SignedGap through_signed = gap::signed_gap(through_ratios);
    d.unmodelled_gap = through_signed.unmodelled;
    d.unmodelled_critical = critical_value(through.unmodelled, options.alpha);
    d.p_value = p_value_of(d.unmodelled_gap, through.unmodelled);
    d.significant = d.p_value < options.alpha;
    d.own_noise_less.value = through_signed.pessimistic;
    d.own_noise_less.critical = critical_value(through.pessimistic, options.alpha);
    d.own_noise_less.p_value = p_value_of(through_signed.pessimistic, through.pessimistic);
    d.own_noise_less.significant = through_signed.pessimistic > 0 && d.own_noise_less.p_value < options.alpha;
    d.null_kind = "the model and the sensor's noise through the import";
    d.statements.push_back(import->description);
  }
  if (!d.against_model.reported) {
    d.estimate_test = test_run_estimates(p, analysers, null, options, d.p_value);
    if (d.estimate_test.measured) d.significant = d.estimate_test.combined_p < options.alpha;
  }
  if (n < 20)
    d.statements.push_back(fmt::format("{} runs: the gap's power is reduced (a null file of {} runs scatters "
                                       "up to G = {:.3g} at alpha = {})", n, n, d.null_gap_critical, options.alpha));

  // Where it lies.
  d.where = locate_gap(p, analysers, observed, null, null_z, null_layout, options.alpha, d.pessimistic.significant,
                       own_noise ? &*own_noise : nullptr);
  own_noise.reset();

  // Which effect, and how far the gap shrinks.
  if (n < options.minimum_runs) {
    d.statements.push_back(fmt::format("{} runs: too few to fit candidate effects on one half and score them on "
                                       "the other (at least {} needed); no ranking", n, options.minimum_runs));
    return with_raw_stage(std::move(d), file);
  }
  if (!d.model_gap_significant()) {
    d.statements.push_back(fmt::format("no significant gap against the model (p = {:.3g} >= alpha = {}): no effect is selected",
                                       d.against_model.reported  ? d.against_model.p_value
                                       : d.estimate_test.measured ? d.estimate_test.combined_p
                                                                  : d.p_value,
                                       options.alpha));
  }
  if (options.rank == RankWhen::kNever || (options.rank == RankWhen::kIfSignificant && !d.model_gap_significant())) {
    d.statements.push_back("candidate effects not fitted (--rank)");
    return with_raw_stage(std::move(d), file);
  }
  Selection selection = rank_and_select(d, p, null, options);
  d.first = std::move(selection.first);
  d.greedy = std::move(selection.greedy);
  d.selected = std::move(selection.selected);
  for (std::string& s : selection.statements) d.statements.push_back(std::move(s));
  if (InsidePriors named = name_inside_priors(d); named.statement) {
    d.statements.push_back(std::move(*named.statement));
    if (named.top) {
      d.estimate_test.replaced_top = d.first.top.empty() ? "(none)" : d.first.top;
      d.first.top = std::move(*named.top);
    }
  }
  if (d.model_gap_significant() && d.ranked())
    if (std::optional<CandidateResult> checked = check_finding(d.first.ranking[0], p, records.file, null, options)) {
      // The greedy search's first step is the same finding when it names the same effect.
      if (!d.greedy.empty() && d.greedy[0].effect == checked->effect) d.greedy[0].parameters = checked->parameters;
      d.first.ranking[0] = std::move(*checked);
    }
  for (std::string& s : ranking_limits(d)) d.statements.push_back(std::move(s));
  return with_raw_stage(std::move(d), file);
}

}  // namespace insmc::gap
