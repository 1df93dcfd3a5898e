#pragma once
/// The gap diagnosis written out: gap.json (machines) and gap.md with its
/// SVG plots (people). Shape of the JSON: docs/gap.md.
#include <string>
#include <utility>
#include <vector>

#include "montecarlo/gap/diagnosis.h"
#include "montecarlo/write/json.h"

namespace insmc::mc {

Json diagnosis_json(const Diagnosis& d, const std::vector<std::string>& record_files);

/// The site's values with their sources and reasons, keyed by header key
/// (gap.json's and compensate.json's "site").
Json site_values_json(const std::vector<SiteValue>& values);

/// (file name, contents): gap.md and its plots.
/// The names of the files diagnosis_report returns, and gap.json beside them
/// (the output folder is checked for them before the work).
std::vector<std::string> diagnosis_file_names();

std::vector<std::pair<std::string, std::string>> diagnosis_report(const Diagnosis& d,
                                                                  const std::vector<std::string>& record_files);

}  // namespace insmc::mc
