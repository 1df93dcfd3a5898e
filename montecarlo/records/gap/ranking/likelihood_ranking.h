#pragma once
/// The maximum-likelihood side of the first ranking (docs/gap-method.md §4). The
/// ranking itself stays by held-out G (ranking.h); beside it the best
/// candidates by held-out G are fitted by maximum likelihood between their
/// physical limits (fit/likelihood_fit.h), with profile intervals, their
/// held-out log-likelihood gain over the model without them (2-fold, as the
/// ranking splits) and that gain's reference on null files of the records'
/// size; and the pairs of the best few, fitted jointly.
#include <vector>

#include "montecarlo/records/gap/diagnosis_options.h"
#include "montecarlo/records/gap/diagnosis_results.h"
#include "montecarlo/records/gap/fit/candidate_fit.h"
#include "montecarlo/records/gap/null/null_calibration.h"
#include "montecarlo/records/gap/ranking/ranking.h"

namespace insmc::gap {

/// Fills d.ranking[i].likelihood for the first options.likelihood_candidates
/// of `ranked` (d.ranking in the same order) and d.pairs for the pairs of the
/// first options.likelihood_pair_candidates.
void record_likelihood(Diagnosis& d, const std::vector<Scored>& ranked, const runs::PreparedRuns& p, const ModelNull& null,
                       const DiagnosisOptions& options);

}  // namespace insmc::gap
