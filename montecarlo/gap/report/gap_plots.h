#pragma once
/// The diagnosis' two plots (docs/gap.md §3): the groups' ln ratios by name
/// with the null band, and the Allan deviation of the f residuals on log–log
/// axes with the null band. Axis ranges come from the values drawn; every
/// mark is clipped to the frame.
#include <string>

#include "montecarlo/gap/diagnosis.h"

namespace insmc::mc {

std::string groups_svg(const Diagnosis& d);
std::string allan_svg(const Diagnosis& d);

}  // namespace insmc::mc
