#pragma once
/// sensitivity.csv: the linear map of each output that depends on the
/// uncertainty vector x alone (e.g. scheme none): its x, y, z, north and
/// east position errors at each report time as coefficients on the
/// catalogue's parameters, in metres per SI unit of the parameter (the
/// si_unit column of `insmc params`). With the parameters' distributions it
/// is the whole uncompensated study, for a user's own tools (the NumPy
/// reference of docs/performance.md reads it). Outputs that also depend on
/// the test run's quantisation, noise or redraws are left out: their map
/// acts on more than x.
#include <string>

#include "montecarlo/study/model/study_map.h"

namespace insmc::mc {

std::string render_sensitivity_csv(const StudyLayout& layout, const StudyMap& map);

}  // namespace insmc::mc
