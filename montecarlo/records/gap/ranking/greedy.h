#pragma once
/// Which effect and how far: the candidates ranked
/// (ranking.h), then the best added greedily while the held-out gap stays
/// significant, each step's shrink measured on held-out runs.
#include "montecarlo/records/gap/diagnosis_options.h"
#include "montecarlo/records/gap/diagnosis_results.h"
#include "montecarlo/records/gap/fit/candidate_fit.h"
#include "montecarlo/records/gap/null/null_calibration.h"

namespace insmc::gap {

/// Fills d's ranking and greedy steps (d.gap, d.significant and d.runs set).
void rank_and_select(Diagnosis& d, const runs::PreparedRuns& p, const ModelNull& null, const DiagnosisOptions& options);

}  // namespace insmc::gap
