#pragma once
/// What a diagnosis finds (`insmc gap`, docs/gap-method.md): the result of each
/// stage, gathered in a Diagnosis. The stages fill these in; the report
/// (report/) and the validation (validation/) read them.
#include <algorithm>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "lib/units/quantity.h"
#include "montecarlo/records/gap/metric/gap_metric.h"
#include "montecarlo/records/runs/files/layout.h"
#include "montecarlo/records/runs/files/site_values.h"

namespace insmc::gap {

struct GroupResult {
  bool coherent = false;   ///< a coherent group (what all runs share), else a scatter group
  int group = 0;           ///< index among its kind (layout.h)
  double count = 0;        ///< terms over all runs
  double power = 0;        ///< observed mean z² (coherent: m |mean z|² per term)
  double null_power = 0;   ///< the model's expectation of it, calibrated on the null
  double log_ratio = 0;    ///< ℓ
  double p_value = 1;      ///< of |ℓ| against the null files
  double share = 0;        ///< ℓ² / Σ ℓ²
  double null_low = 0, null_high = 0;  ///< the null files' ℓ, quantiles α/2 and 1 − α/2
  /// Where the sensor's own noise through the import puts ℓ (the same
  /// expectation, the model's): its null files' quantiles α/2 and 1 − α/2;
  /// NaN without that null (null/import_null.h).
  double own_noise_low = std::numeric_limits<double>::quiet_NaN();
  double own_noise_high = std::numeric_limits<double>::quiet_NaN();
  /// The scatter group whose stage, axis and window this group reports.
  int representative() const { return coherent ? runs::coherent_representative(group) : group; }
  std::string name() const { return coherent ? runs::coherent_group_name(group) : runs::group_name(group); }
};

struct Share {
  std::string name;
  double share = 0;
};

struct TimeFunctionShares {
  int axis = 0;
  std::vector<Share> shares;  ///< of the post-test r innovation energy
};

struct AllanPoint {
  double cluster_s = 0;
  double observed = 0;  ///< Allan deviation of the f residuals [m/s²]
  double null = 0;      ///< the same of the null runs
  /// 5–95 % of the same over null files of the records' size (the null band).
  double null_low = 0, null_high = 0;
  /// The same three of null runs with the sensor's own noise through the
  /// import; 0 without that null.
  double own_noise = 0, own_noise_low = 0, own_noise_high = 0;
};

struct AllanCurve {
  int axis = 0;
  std::vector<AllanPoint> points;
};

/// How the fit of a parameter behaves on files simulated with the finding
/// (ranking/finding_check.h): their mean fitted value over the simulated
/// one, as a ratio (logarithmic) or a difference (linear), and the spread.
struct SimulatedCheck {
  bool measured = false;
  int files = 0;
  double simulated = 0;  ///< the value simulated (SI)
  bool logarithmic = true;
  double bias = 0;       ///< mean of ln(fitted) − ln(simulated), or of fitted − simulated
  double spread = 0;     ///< standard deviation of the same over the files
};

struct ParameterEstimate {
  std::string name;
  Dimension dimension = Dimension::kDimensionless;
  /// Value of least G (between grid points, fit/subgrid.h) and the 16–84 %
  /// range of the fits on resampled runs; for the first-ranked finding both
  /// corrected by `check` when it was measured.
  double value = 0, low = 0, high = 0;
  bool at_grid_edge = false;
  SimulatedCheck check;
};

/// A likelihood profile interval (fit/likelihood_fit.h); an open end stays
/// within the drop up to the physical limit, which it then reports.
struct ProfileRange {
  double low = 0, high = 0;
  bool open_low = false, open_high = false;
};

/// A parameter's maximum-likelihood value between its physical limits
/// (CandidateParameter::lower_si, upper_si), with profile intervals; an
/// amplitude keeps its least-squares value (no intervals).
struct MlParameter {
  std::string name;
  Dimension dimension = Dimension::kDimensionless;
  double value = 0;
  bool least_squares = false;  ///< an amplitude: the least-squares fit's value
  bool intervals = false;      ///< ci68 and ci95 measured
  ProfileRange ci68, ci95;
  bool at_limit = false;       ///< the maximum sits at a physical limit
};

/// The maximum-likelihood side of a candidate or a pair (docs/gap-method.md §4).
struct LikelihoodResult {
  bool fitted = false;
  std::vector<MlParameter> parameters;
  /// Held-out log-likelihood gain over the model without it, 2-fold [nats],
  /// and the same on null files of the records' size (median); NaN when not measured.
  double heldout_gain = std::numeric_limits<double>::quiet_NaN();
  double null_gain = std::numeric_limits<double>::quiet_NaN();
  int evaluations = 0;  ///< model builds the fits made
};

struct CandidateResult {
  std::string effect;
  std::string description;
  std::vector<ParameterEstimate> parameters;
  double heldout_gap_after = 0;
  double shrink = 0;
  /// The same candidate's held-out shrink on null files of the records'
  /// size (runs of the null calibration split the same way; the median over
  /// those files): what it gains on noise alone. NaN when not measured.
  double null_shrink = std::numeric_limits<double>::quiet_NaN();
  LogRatios heldout_log_ratios{};  ///< ℓ on held-out runs with the effect added
  LikelihoodResult likelihood;          ///< fitted for the top candidates only
  /// The finding as `insmc simulate --effect` takes it (ranking/effect_terms.h;
  /// empty when the candidate's parameters are not the effect's), and the
  /// effect's parameters it keeps at a default or a header value, with why.
  std::string as_effect;
  std::vector<std::string> as_effect_kept;
  /// The resampling standard error of this candidate's held-out G less the
  /// first-ranked one's (runs drawn with replacement); NaN for the first.
  double behind_first_se = std::numeric_limits<double>::quiet_NaN();
};

/// Two of the top candidates together, their parameters fitted jointly.
struct PairResult {
  std::string first, second;
  LikelihoodResult likelihood;
};

struct GreedyStep {
  std::string effect;
  std::vector<ParameterEstimate> parameters;
  double heldout_gap = 0;
  double p_value = 1;  ///< of the held-out G₊ (an unmodelled effect left)
};

/// The other direction of the gap (gap_metric.h SignedGap): the data show
/// less scatter or less in common than the model, with its own critical
/// value at alpha from the same null files.
/// How far Table 3.1's priors would have to be scaled for these runs: every
/// variance × s², s of least G over all runs (where/prior_scale.h).
struct PriorScale {
  bool measured = false;
  double scale = 1;              ///< s
  double low = 1, high = 1;      ///< 16–84 % of 200 resampled fits
  bool at_limit = false;         ///< s at an end of its range [0.01, 100]
  double pessimistic_after = 0;  ///< G₋ with the priors so scaled
  bool explains = false;         ///< G₋ after at most the null's critical value
};

struct PessimisticFinding {
  double value = 0;        ///< G₋
  double p_value = 1;      ///< share of null files with G₋ at least this
  double critical = 0;     ///< the G₋ to exceed for p ≤ α (critical_value)
  bool significant = false;
  PriorScale prior_scale;          ///< measured when significant
};

/// The verdict against the model alone when the main one is against the
/// null through the import (null/import_null.h): G₊ of the data against
/// null files of the model with a perfect sensor. The report gives it first.
struct ModelOnlyVerdict {
  bool reported = false;
  double value = 0, critical = 0, p_value = 1;  ///< G₊, its critical value, p
  bool significant = false;
  double gap = 0, null_gap_critical = 0;        ///< G and its critical value
  double null_gap_median = 0;                   ///< G's median on the null files
};

/// G₋ against the null through the import: the data scatter less than the
/// sensor's own fitted noise makes them (a raw stage that overstates it).
struct OwnNoiseLess {
  double value = 0, critical = 0, p_value = 1;  ///< G₋, its critical value, p
  bool significant = false;
};

/// One estimate of the test run against the prior (where/estimate_test.h):
/// its three statistics over the runs, each with the null files' critical
/// value at alpha (no correction for the table's many tests) and its p.
struct EstimateStatistics {
  std::string name;        ///< catalogue name of the x column (`insmc params`)
  double reach = 0;        ///< the prior's reach: the null runs' 99 % point of |ĉ| (normalized)
  double beyond = 0, beyond_critical = 0, beyond_p = 1;  ///< share of runs beyond the reach
  double spread = 0, spread_critical = 0, spread_p = 1;  ///< variance over runs / the null runs'
  double mean = 0, mean_critical = 0, mean_p = 1;        ///< |mean over runs − null mean| in null standard errors
};

/// A candidate scored on the estimates alone: the per-run estimates' Gaussian
/// log-likelihood with the candidate's mean shift and added covariance,
/// fitted on one half of the runs and scored on the other (2-fold), less the
/// null's on the same runs [nats].
struct EstimateScore {
  std::string effect;
  double heldout_gain = 0;
};

/// The test of the per-run estimates against the prior (docs/gap-method.md §2).
struct EstimateTest {
  bool measured = false;
  std::vector<EstimateStatistics> estimates;
  double min_p = 1;       ///< least p of the table
  double family_p = 1;    ///< of min_p against the null files' own least p
  bool significant = false;
  double combined_p = 1;  ///< of min(p of G+, min_p) against the same of the null files
  std::vector<EstimateScore> scores;  ///< candidates that act inside the priors, by held-out gain
  std::string named;                  ///< the first, or a class "a|b" within 1.92 nats
  std::string told_apart_by;          ///< for a class: the test that would split it
  std::string reason;                 ///< why not measured
  std::string replaced_top;           ///< the ranking's top when the estimates' name replaced it
};

/// Where one diagnosis' gap lies.
struct GapLocation {
  std::vector<GroupResult> groups;
  std::vector<std::string> pessimistic_where;  ///< where a significant pessimistic finding lies, most negative ℓ first
  std::vector<Share> by_kind, by_axis, by_stage, by_window;
  std::vector<TimeFunctionShares> time_functions;
  std::vector<AllanCurve> allan;
};

/// The effects a top names: one, or each member of a class "a|b".
inline std::vector<std::string> class_members(const std::string& top) {
  std::vector<std::string> out;
  for (std::size_t b = 0, e; b <= top.size(); b = e + 1) {
    e = std::min(top.find('|', b), top.size());
    out.push_back(top.substr(b, e - b));
  }
  return out;
}

/// The first ranking as the report gives it.
struct FirstRanking {
  std::vector<CandidateResult> ranking;  ///< ascending held-out gap
  std::string top;                       ///< effect or class "a|b"
  double runner_up_margin = 0, runner_up_margin_se = 0;
  std::vector<PairResult> pairs;         ///< of the top candidates, by held-out log-likelihood gain
};

/// A record far beyond what the model and its null runs give for any row:
/// a corrupt value or a jump in the logger, not an effect (where/outliers.h).
struct OutlierRow {
  std::int64_t run = 0;
  double t_s = 0;
  std::string component;  ///< "f_x", "r_y", ...
  double z = 0;           ///< normalized residual under the model
};
struct Outliers {
  double threshold = 0;             ///< |z| beyond which a row is listed
  int count = 0;                    ///< runs with a row beyond it
  /// In at most a tenth of the runs (at least one): a record of its own,
  /// said first. In more, it is what an effect does to every run (a strong
  /// sway puts every run past it), and the ranking reads it.
  bool isolated = false;
  std::vector<OutlierRow> largest;  ///< each such run's largest |z|, the largest first, at most kListedOutliers
};
inline constexpr int kListedOutliers = 10;

/// The r rows the model does not read, screened against those it reads
/// (where/unread_rows.h).
struct UnreadRow {
  std::int64_t run = 0;
  double t_s = 0;
  std::string component;    ///< "r_x", "r_y", "r_z"
  double deviation_m = 0;   ///< from the line through the read rows
  double bound_m = 0;       ///< ten times the resolution's and the curvature's reach
};

struct UnreadRows {
  int read = 0, unread = 0;  ///< r rows (times) of the runs' navigation and test phases
  int beyond = 0;            ///< unread values (row × axis) beyond their bound
  int runs_beyond = 0, runs = 0;
  std::vector<UnreadRow> largest;  ///< the largest deviation over its bound first, at most kListedUnread
};
inline constexpr int kListedUnread = 5;

struct Diagnosis {
  int runs = 0;
  std::string scheme = "none";  ///< the records' scheme (header)
  int calibration_runs = 0;
  std::vector<std::string> statements;  ///< what the data cannot support, plainly
  Outliers outliers;
  UnreadRows unread;  ///< the r rows the model does not read, screened (where/unread_rows.h)
  std::vector<runs::SiteValue> site;          ///< every value of the site the null uses, with its source
  /// From a raw-sensor stage (records/raw_stage.h; 0 without one): the
  /// gyros' and accelerometers' fitted noise over one Schuler period over
  /// Table 3.1's bounds, the largest axis of each.
  double raw_gyro_ratio = 0, raw_accel_ratio = 0;
  /// G (two-sided, what the candidates shrink); p_value and significant are
  /// those of an unmodelled effect: the one-sided G₊ against the null's.
  double gap = 0, p_value = 1, alpha = 0.01;
  bool significant = false;
  double null_gap_median = 0, null_gap_critical = 0;  ///< of G: the median and the critical value (critical_value: beyond it ⟺ p ≤ α)
  double unmodelled_gap = 0, unmodelled_critical = 0;  ///< G₊ and its critical value on the null
  PessimisticFinding pessimistic;
  /// What the null is: "the model" or "the model and the sensor's noise through the import".
  std::string null_kind = "the model";
  ModelOnlyVerdict against_model;
  OwnNoiseLess own_noise_less;  ///< measured when against_model.reported
  GapLocation where;
  double heldout_gap_before = 0;
  FirstRanking first;                     ///< the candidates ranked (empty when none was scored or ranking was not run)
  std::vector<GreedyStep> greedy;         ///< the effects added, in order
  std::vector<std::string> selected;
  EstimateTest estimate_test;

  /// The gap the candidates explain: against the model alone (the main
  /// verdict unless the null goes through the import).
  bool ranked() const { return !first.ranking.empty(); }
  bool model_gap_significant() const { return against_model.reported ? against_model.significant : significant; }
  /// The critical G of the model's own null (what the held-out gaps are read against).
  double model_null_gap_critical() const {
    return against_model.reported ? against_model.null_gap_critical : null_gap_critical;
  }
};

}  // namespace insmc::gap
