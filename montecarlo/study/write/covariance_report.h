#pragma once
/// The report of `insmc covariance` (montecarlo/report/report.h):
/// covariance.csv, covariance_grid.csv, budget.csv, sensitivity.csv,
/// covariance.md and the budget figure; stdout the summary, covariance.md
/// (--full), covariance.csv or the settings with the covariance (json).
#include "montecarlo/report/length_unit.h"
#include "montecarlo/report/report.h"
#include "montecarlo/study/model/study_map.h"

namespace insmc::mc {

ReportOutline covariance_report_outline();

Report covariance_report(const StudyConfig& config, const StudyLayout& layout, const StudyMap& map, LengthUnit unit);

}  // namespace insmc::mc
