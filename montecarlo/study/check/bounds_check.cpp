#include "montecarlo/study/check/bounds_check.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

#include "lib/common/assert.h"
#include "montecarlo/report/csv.h"
#include "montecarlo/report/interval_format.h"

namespace insmc::mc {
namespace {

/// Output o's estimate of the bound's metric with its interval at the
/// two-sided level `confidence`.
QuantileEstimate estimate(BoundMetric metric, const StudyLayout& layout, const StudyAccumulator& acc, std::size_t o,
                          double confidence) {
  const OutputSummary sum = acc.outputs()[o].summarize(confidence);
  if (metric == BoundMetric::kRms) return {sum.rms, sum.rms_lo, sum.rms_hi};
  // 2DRMS = 2 · the horizontal RMS, its interval twice the RMS's
  // (docs/outputs.md, "Accuracy metrics").
  if (metric == BoundMetric::k2drms) return {2 * sum.rms, 2 * sum.rms_lo, 2 * sum.rms_hi};
  // The bounds file allows percentiles on horizontal outputs alone, and
  // their times are the study's report times: their samples are kept.
  const std::optional<HorizontalAccuracy> a = acc.accuracy(layout, o, sum, confidence);
  INSMC_ASSERT(a.has_value(), "a percentile bound on output {} whose samples are not kept", o);
  return metric == BoundMetric::kCep50 ? a->cep50_m : a->cep95_m;
}

/// The one-sided upper confidence limit at level c (a bound is a one-sided
/// claim: the metric is at most it with probability c): the upper end of
/// the two-sided interval at 2c - 1. At c = 0.5 that interval shrinks to
/// the estimate itself, which is then the limit.
QuantileEstimate one_sided_upper(BoundMetric metric, const StudyLayout& layout, const StudyAccumulator& acc,
                                 std::size_t o, double c) {
  const double two_sided = 2 * c - 1;
  if (two_sided > 0) return estimate(metric, layout, acc, o, two_sided);
  QuantileEstimate e = estimate(metric, layout, acc, o, 0.5);
  e.lo = e.hi = e.value;
  return e;
}

template <class T>
void add_once(std::vector<T>& v, const T& x) {
  if (std::find(v.begin(), v.end(), x) == v.end()) v.push_back(x);
}

}  // namespace

StudyConfig config_for_bounds(StudyConfig config, const std::vector<Bound>& bounds) {
  config.systems.clear();
  config.schemes.clear();
  config.report_times_s.clear();
  config.with_grid = false;
  for (const Bound& b : bounds) {
    add_once(config.systems, b.system);
    add_once(config.schemes, b.scheme);
    add_once(config.report_times_s, b.t_s);
  }
  validate(config);
  return config;
}

std::vector<BoundVerdict> judge_bounds(const std::vector<Bound>& bounds, const StudyConfig& config,
                                       const StudyLayout& layout, const StudyAccumulator& acc) {
  std::vector<BoundVerdict> verdicts;
  for (const Bound& b : bounds) {
    for (std::size_t o = 0; o < layout.outputs.size(); ++o) {
      const auto& s = layout.outputs[o];
      if (s.scheme != b.scheme || s.system != b.system || s.axis != b.axis ||
          std::abs(layout.times_s[s.time_index] - b.t_s) > 1e-6)
        continue;
      BoundVerdict v{b, b.confidence.value_or(config.confidence), {}, false};
      v.estimate = one_sided_upper(b.metric, layout, acc, o, v.confidence);
      v.holds = v.estimate.hi <= b.limit_m;  // violated unless the upper limit lies at or below the bound
      verdicts.push_back(v);
    }
  }
  return verdicts;
}

ReportOutline check_report_outline() { return {"check", {}, {}, {ReportFormat::kMarkdown}}; }

Report check_report(const std::vector<BoundVerdict>& verdicts, std::optional<LengthUnit> units) {
  std::string text;
  for (const BoundVerdict& v : verdicts) {
    const Bound& b = v.bound;
    const QuantileEstimate& e = v.estimate;
    // The estimate to the place its interval supports.
    const LengthUnit u = units.value_or(b.unit);
    const double k = length_factor(u);
    const std::optional<int> place = interval_place(k * (e.hi - e.value));
    const auto at_place = [&](double x) { return place ? format_at_place(x, *place) : format_significant(x, 6); };
    text += fmt::format("{} line {}: scheme={} system={} axis={} t_min={}: {} {} {}, one-sided upper {}% confidence "
                        "limit {} {} {} bound {} {}\n",
                        v.holds ? "ok      " : "VIOLATED", b.line, to_string(b.scheme), system_number(b.system),
                        to_string(b.axis), format_number(b.t_s / 60), names_of(b.metric).label, at_place(k * e.value),
                        length_suffix(u), format_number(100 * v.confidence), at_place(k * e.hi), length_suffix(u),
                        v.holds ? "<=" : ">", fmt::format("{:.6g}", k * b.limit_m), length_suffix(u));
  }
  Report report(check_report_outline());
  report.shown(ReportFormat::kMarkdown, std::move(text));
  return report;
}

}  // namespace insmc::mc
