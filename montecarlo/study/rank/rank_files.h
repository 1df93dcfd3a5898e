#pragma once
/// The output of `insmc rank` (README, "Ranking the schemes"): ranking.csv,
/// breakeven.csv, rank.md, rank.json's results and the figure of each
/// scheme's RMS along every decisive assumption with the crossings marked.
/// Rendered to strings first, so that nothing is written unless everything
/// was computed.
#include <string>

#include "montecarlo/study/rank/break_even.h"
#include "montecarlo/study/rank/scheme_order.h"
#include "montecarlo/report/length_unit.h"
#include "montecarlo/report/report.h"

namespace insmc::mc {

/// rank's set; stdout the summary (the order at the last report time and
/// the first place's limits), rank.md (--full), ranking.csv or rank.json.
ReportOutline rank_report_outline();

/// Lengths in `unit` (--units) in the CSV, Markdown, summary and figure;
/// rank.json (the settings and the results) stays in SI (`rms_m`), as
/// run.json does.
Report rank_report(const StudyConfig& config, const std::vector<SchemeOrder>& orders, const BreakEven& even,
                   LengthUnit unit);

}  // namespace insmc::mc
