// insmc check --bounds FILE: statistical bounds for users' CI. Runs the study
// the bounds need and exits 1 naming every bound whose upper confidence
// one-sided upper confidence limit of its metric (the RMS, or CEP50 / CEP95
// / 2DRMS of the horizontal radial error: docs/outputs.md, "Accuracy
// metrics") exceeds it, 0 when all hold,
// 2 for a malformed file.
#include <fmt/format.h>

#include "apps/cli_common.h"
#include "apps/study_options.h"
#include "lib/common/assert.h"
#include "lib/common/input_error.h"
#include "lib/units/units.h"
#include "montecarlo/study/check/bounds_file.h"
#include "montecarlo/report/interval_format.h"
#include "montecarlo/study/engine/engine.h"
#include "montecarlo/report/csv.h"

namespace insmc::app {
namespace {

/// Output o's estimate of the bound's metric with its interval at the
/// two-sided level `confidence`.
mc::QuantileEstimate estimate(mc::BoundMetric metric, const mc::StudyLayout& layout, const mc::StudyAccumulator& acc,
                              std::size_t o, double confidence) {
  const mc::OutputSummary sum = acc.outputs()[o].summarize(confidence);
  if (metric == mc::BoundMetric::kRms) return {sum.rms, sum.rms_lo, sum.rms_hi};
  // 2DRMS = 2 · the horizontal RMS, its interval twice the RMS's
  // (docs/outputs.md, "Accuracy metrics").
  if (metric == mc::BoundMetric::k2drms) return {2 * sum.rms, 2 * sum.rms_lo, 2 * sum.rms_hi};
  // The bounds file allows percentiles on horizontal outputs alone, and
  // their times are the study's report times: their samples are kept.
  const std::optional<mc::HorizontalAccuracy> a = acc.accuracy(layout, o, sum, confidence);
  INSMC_ASSERT(a.has_value(), "a percentile bound on output {} whose samples are not kept", o);
  return metric == mc::BoundMetric::kCep50 ? a->cep50_m : a->cep95_m;
}

/// The one-sided upper confidence limit at level c (a bound is a one-sided
/// claim: the metric is at most it with probability c): the upper end of
/// the two-sided interval at 2c - 1. At c = 0.5 that interval shrinks to
/// the estimate itself, which is then the limit.
mc::QuantileEstimate one_sided_upper(mc::BoundMetric metric, const mc::StudyLayout& layout,
                                     const mc::StudyAccumulator& acc, std::size_t o, double c) {
  const double two_sided = 2 * c - 1;
  if (two_sided > 0) return estimate(metric, layout, acc, o, two_sided);
  mc::QuantileEstimate e = estimate(metric, layout, acc, o, 0.5);
  e.lo = e.hi = e.value;
  return e;
}

}  // namespace

int run_check(const Args& args) {
  po::options_description opts("Options");
  opts.add_options()("bounds", po::value<std::string>(),
                     "file of bounds, one a line: scheme=none system=2 axis=horizontal t_min=84 "
                     "rms_m<=9000 [confidence=0.95, one-sided, in [0.5, 0.999999]]; also rms_ft, rms_nmi, rms<=5nmi, and on "
                     "axis=horizontal cep50_m<=N, cep95_m<=N (or p95_m) and 2drms_m<=N; # comments");
  opts.add(study_options_description(true));
  const auto vm = parse_args(args, "check", "--bounds FILE [study options]", opts);
  if (!vm) return 0;
  if (!vm->count("bounds")) throw InputError("--bounds", "(missing)", "give the file of bounds to check");
  const std::string bounds_path = (*vm)["bounds"].as<std::string>();
  const std::vector<mc::Bound> bounds =
      read_input("--bounds", bounds_path, [&] { return mc::read_bounds_file(bounds_path); });
  mc::StudyConfig config = read_study_config(*vm, true);
  const mc::LengthUnit unit = read_length_unit(*vm);
  const bool units_given = !(*vm)["units"].defaulted();
  // Run exactly what the bounds need: their systems, schemes and times.
  config.systems.clear();
  config.schemes.clear();
  config.report_times_s.clear();
  config.with_grid = false;
  for (const mc::Bound& b : bounds) {
    if (std::find(config.systems.begin(), config.systems.end(), b.system) == config.systems.end())
      config.systems.push_back(b.system);
    if (std::find(config.schemes.begin(), config.schemes.end(), b.scheme) == config.schemes.end())
      config.schemes.push_back(b.scheme);
    if (std::find(config.report_times_s.begin(), config.report_times_s.end(), b.t_s) == config.report_times_s.end())
      config.report_times_s.push_back(b.t_s);
  }
  mc::validate(config);
  const mc::StudyLayout layout = mc::make_layout(config);
  const mc::StudyMap map(config, layout);
  const mc::StudyAccumulator acc = mc::run_blocks(config, map, 0, mc::block_count(config.samples));
  int violated = 0;
  for (const mc::Bound& b : bounds) {
    for (size_t o = 0; o < layout.outputs.size(); ++o) {
      const auto& s = layout.outputs[o];
      if (s.scheme != b.scheme || s.system != b.system || s.axis != b.axis ||
          std::abs(layout.times_s[s.time_index] - b.t_s) > 1e-6)
        continue;
      const double conf = b.confidence.value_or(config.confidence);
      const mc::QuantileEstimate e = one_sided_upper(b.metric, layout, acc, o, conf);
      // Violated unless the upper confidence limit lies at or below the bound.
      const bool ok = e.hi <= b.limit_m;
      if (!ok) ++violated;
      // In --units when given, else in the unit the bound was written in;
      // the estimate to the place its interval supports.
      const mc::LengthUnit u = units_given ? unit : b.unit;
      const double k = mc::length_factor(u);
      const std::optional<int> place = mc::interval_place(k * (e.hi - e.value));
      const auto at_place = [&](double x) { return place ? mc::format_at_place(x, *place) : mc::format_significant(x, 6); };
      fmt::print("{} line {}: scheme={} system={} axis={} t_min={}: {} {} {}, one-sided upper {}% confidence limit {} "
                 "{} {} bound {} {}\n",
                 ok ? "ok      " : "VIOLATED", b.line, to_string(b.scheme), system_number(b.system),
                 to_string(b.axis), mc::format_number(b.t_s / 60), mc::names_of(b.metric).label,
                 at_place(k * e.value), mc::length_suffix(u), mc::format_number(100 * conf), at_place(k * e.hi),
                 mc::length_suffix(u), ok ? "<=" : ">", fmt::format("{:.6g}", k * b.limit_m), mc::length_suffix(u));
    }
  }
  if (violated) fmt::print(stderr, "insmc check: {} of {} bounds violated\n", violated, bounds.size());
  return violated ? 1 : 0;
}

}  // namespace insmc::app
