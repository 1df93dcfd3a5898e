#pragma once
/// The report's first sentence: the finding that matters most for a
/// decision about the unit, in this order (docs/gap.md, "The leading
/// finding"): the unit's counts lie outside the model's assumptions (a pulse
/// weight or position resolution far from the report's 0.1 ft/s and 3 ft),
/// its errors outside the model's priors (`bounds` chosen), an unmodelled
/// effect (which, how much of the gap it closes), the model is pessimistic,
/// or the data agree with the model. Records that came through the import
/// with its raw stage also get the unit's noise against Table 3.1 and the two
/// verdicts (report/verdicts_report.h): against the model, then against the
/// unit's own noise.
#include <string>

#include "montecarlo/records/gap/diagnosis.h"

namespace insmc::gap {

/// A factor beyond which a site value is "far from the model's".
inline constexpr double kFarFromModel = 2.0;

std::string leading_finding(const Diagnosis& d);

}  // namespace insmc::gap
