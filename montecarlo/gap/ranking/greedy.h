#pragma once
/// Which effect and how far: the candidates ranked
/// (ranking.h), then the best added greedily while the held-out gap stays
/// significant, each step's shrink measured on held-out runs.
#include "montecarlo/gap/diagnosis.h"
#include "montecarlo/gap/fit/candidate_fit.h"
#include "montecarlo/gap/null/null_calibration.h"

namespace insmc::mc {

/// Fills d's ranking and greedy steps (d.gap, d.significant and d.runs set).
void rank_and_select(Diagnosis& d, const PreparedRuns& p, const Null& null, const DiagnosisOptions& options);

}  // namespace insmc::mc
