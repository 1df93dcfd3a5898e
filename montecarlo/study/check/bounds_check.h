#pragma once
/// `insmc check`: the study a bounds file needs (its systems, schemes and
/// report times, nothing else) and each bound judged against the one-sided
/// upper confidence limit of its metric (the RMS, or CEP50 / CEP95 / 2DRMS
/// of the horizontal radial error: docs/outputs.md, "Accuracy metrics").
/// A bound holds when that limit lies at or below it.
#include <optional>
#include <vector>

#include "montecarlo/report/report.h"
#include "montecarlo/study/aggregate/order_statistics.h"
#include "montecarlo/study/check/bounds_file.h"
#include "montecarlo/study/engine/engine.h"

namespace insmc::mc {

/// `config` narrowed to what `bounds` need (no grid), validated.
StudyConfig config_for_bounds(StudyConfig config, const std::vector<Bound>& bounds);

struct BoundVerdict {
  Bound bound;
  double confidence = 0;       ///< one-sided: the bound's own, else the study's
  QuantileEstimate estimate;   ///< value, and in `hi` the upper confidence limit
  bool holds = false;
};

/// Every bound against every output it names, in the file's order.
std::vector<BoundVerdict> judge_bounds(const std::vector<Bound>& bounds, const StudyConfig& config,
                                       const StudyLayout& layout, const StudyAccumulator& acc);

/// check prints a line per verdict (markdown only, no set): lengths in
/// `units` when given, else in the unit each bound was written in.
ReportOutline check_report_outline();
Report check_report(const std::vector<BoundVerdict>& verdicts, std::optional<LengthUnit> units);

}  // namespace insmc::mc
