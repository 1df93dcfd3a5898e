#pragma once
/// The gap diagnosis written out: gap.json (machines) and gap.md with its
/// SVG plots (people). Shape of the JSON: docs/gap.md.
#include <string>
#include <utility>
#include <vector>

#include "montecarlo/records/gap/diagnosis.h"
#include "montecarlo/report/json.h"
#include "montecarlo/report/report.h"

namespace insmc::gap {

/// The site's values with their sources and reasons, keyed by header key
/// (gap.json's and compensate.json's "site").

/// gap's set: gap.md (which shows the figures' PNGs), gap.json and the
/// figures gap_groups and gap_allan; stdout gap.md (markdown) or gap.json.
mc::ReportOutline diagnosis_report_outline();

/// The report of `d`; `record_files`: the record files as the user named them.
mc::Report diagnosis_report(const Diagnosis& d, const std::vector<std::string>& record_files);

}  // namespace insmc::gap
