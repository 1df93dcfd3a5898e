#pragma once
/// The gap diagnosis written out: gap.json (machines) and gap.md with its
/// SVG plots (people). Shape of the JSON: docs/gap.md.
#include <string>
#include <utility>
#include <vector>

#include "montecarlo/records/gap/diagnosis.h"
#include "montecarlo/report/json.h"

namespace insmc::gap {

mc::Json diagnosis_json(const Diagnosis& d, const std::vector<std::string>& record_files);

/// The site's values with their sources and reasons, keyed by header key
/// (gap.json's and compensate.json's "site").

/// The names of the files besides the figures: gap.md (diagnosis_report)
/// and gap.json (the output folder is checked for them before the work).
std::vector<std::string> diagnosis_file_names();
/// The figures' stems (gnuplot: `.gp`, `.svg`, `.png` each).
std::vector<std::string> diagnosis_figure_stems();

/// gnuplot's renderings of the figures (diagnosis_figure_stems), as
/// (file name, contents).
std::vector<std::pair<std::string, std::string>> diagnosis_figures(const Diagnosis& d);

/// (file name, contents): gap.md (which shows the figures' PNGs).
std::vector<std::pair<std::string, std::string>> diagnosis_report(const Diagnosis& d,
                                                                  const std::vector<std::string>& record_files);

}  // namespace insmc::gap
