#pragma once
/// The output of `insmc rank` (README, "Ranking the schemes"): ranking.csv,
/// breakeven.csv, rank.md, rank.json's results and the figure of each
/// scheme's RMS along every decisive assumption with the crossings marked.
/// Rendered to strings first, so that nothing is written unless everything
/// was computed.
#include <string>

#include "montecarlo/study/rank/break_even.h"
#include "montecarlo/study/rank/scheme_order.h"
#include "montecarlo/report/json.h"
#include "montecarlo/report/length_unit.h"
#include "montecarlo/report/plot/panel_figure.h"

namespace insmc::mc {

struct RankFiles {
  std::string ranking_csv, breakeven_csv, rank_md;
  std::string summary_text;  ///< stdout: the order at the last report time and the first place's limits
  PanelFigure plot;          ///< RMS at the last report time along each assumption, a panel per system
  Json rank_json;
};

/// Lengths in `unit` (--units) in the CSV, Markdown, summary and figure;
/// rank.json stays in SI (`rms_m`), as run.json does.
RankFiles render_rank(const StudyConfig& config, const std::vector<SchemeOrder>& orders, const BreakEven& even,
                      LengthUnit unit);

}  // namespace insmc::mc
