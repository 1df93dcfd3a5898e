#pragma once
/// The error budget as a chart: per scheme, the largest sources of the
/// horizontal mean-square error at the last report time (their shares of
/// E[r²], budget.csv), one bar per system.
#include "montecarlo/study/model/study_map.h"
#include "montecarlo/report/plot/bar_figure.h"

namespace insmc::mc {

/// At most this many sources per scheme: those with the largest share in
/// any system.
inline constexpr std::size_t kBudgetPlotSources = 8;

BarFigure budget_figure(const StudyConfig& config, const StudyLayout& layout, const StudyMap& map);

}  // namespace insmc::mc
