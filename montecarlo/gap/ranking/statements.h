#pragma once
/// After the ranking and greedy steps: their limits, in the report's words.
#include "montecarlo/gap/diagnosis.h"

namespace insmc::mc {

/// What the ranking cannot support, said plainly (docs/gap.md: priors too narrow,
/// effect not identifiable, disturbances masked).
void honest_statements(Diagnosis& d);

}  // namespace insmc::mc
