#pragma once
/// The reports of the two catalogues a study is made from
/// (montecarlo/report/report.h): `insmc params`, Table 3.1's uncertainties
/// with the bound and distribution of each (markdown, csv, json), and
/// `insmc effects`, the truth simulator's named effects with their
/// parameters (markdown, csv). Neither writes a set.
#include "lib/uncertainty/uncertainty_model.h"
#include "montecarlo/report/report.h"

namespace insmc::mc {

ReportOutline params_report_outline();
Report params_report(const UncertaintyModel& model);

ReportOutline effects_report_outline();
Report effects_report();

}  // namespace insmc::mc
