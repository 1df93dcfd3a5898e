#pragma once
/// The maximum-likelihood side of the first ranking (docs/gap-method.md §4). The
/// ranking itself stays by held-out G (ranking.h); beside it the best
/// candidates by held-out G are fitted by maximum likelihood between their
/// physical limits (fit/likelihood_fit.h), with profile intervals, their
/// held-out log-likelihood gain over the model without them (2-fold, as the
/// ranking splits) and that gain's reference on null files of the records'
/// size; and the pairs of the best few, fitted jointly.
#include <string>
#include <vector>

#include "montecarlo/records/gap/diagnosis_options.h"
#include "montecarlo/records/gap/diagnosis_results.h"
#include "montecarlo/records/gap/fit/candidate_fit.h"
#include "montecarlo/records/gap/null/null_calibration.h"
#include "montecarlo/records/gap/ranking/ranking.h"

namespace insmc::gap {

/// The likelihood side of a ranking: the fit of each of the first
/// candidates, in the ranking's order, and the pairs of the first few, the
/// best held-out gain first.
struct LikelihoodRanking {
  std::vector<LikelihoodResult> candidates;
  std::vector<PairResult> pairs;
};

/// The first options.likelihood_candidates of `ranked` (named `effects`, in
/// the same order) fitted by maximum likelihood, and the pairs of the first
/// options.likelihood_pair_candidates.
LikelihoodRanking rank_by_likelihood(const std::vector<Scored>& ranked, const std::vector<std::string>& effects,
                                     const runs::PreparedRuns& p, const ModelNull& null, const DiagnosisOptions& options);

}  // namespace insmc::gap
