#pragma once
/// `insmc run --replay INDEX`: one sample of a study computed again alone:
/// its uncertainties, what its test run and alignment produced (the
/// extended vector z per system) and its errors at the report times.
#include <cstdint>

#include "montecarlo/report/report.h"
#include "montecarlo/study/model/study_map.h"

namespace insmc::mc {

ReportOutline replay_report_outline();

/// `index` < config.samples.
Report replay_report(const StudyConfig& c, const StudyLayout& l, const StudyMap& map, std::uint64_t index);

}  // namespace insmc::mc
