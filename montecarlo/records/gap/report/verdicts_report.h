#pragma once
/// Section 1 of the gap report: the verdicts, in one order. First against
/// the model (Table 3.1's priors: the null every diagnosis has, and what
/// sections 2 to 4 show); then, for records that came through `import-imu`
/// with its raw stage, against the unit's own noise through the import
/// (null/import_null.h). Each is named for what it compares.
#include <string>

#include "montecarlo/records/gap/diagnosis.h"
#include "montecarlo/report/json.h"

namespace insmc::gap {

/// Whether the diagnosis holds the second verdict (the null through the import).
inline bool has_own_noise_verdict(const Diagnosis& d) { return d.against_model.reported; }

/// Section 1's verdict paragraphs (Markdown, each ending in a blank line).
std::string verdicts_markdown(const Diagnosis& d);

/// "Against the model: a significant gap (G+ = 20.6, p = 0.0005); against
/// the unit's own noise through the import: none (G+ = 0.445, p = 0.131)."
std::string verdicts_sentence(const Diagnosis& d);

/// The verdicts in the same order, each with the null it is judged against.
mc::Json verdicts_json(const Diagnosis& d);

}  // namespace insmc::gap
