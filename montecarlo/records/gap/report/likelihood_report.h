#pragma once
/// The maximum-likelihood side of the ranking (ranking/likelihood_ranking.h)
/// in gap.json and gap.md: each fitted candidate's parameters between their
/// physical limits with profile intervals, its held-out log-likelihood gain
/// beside the same gain on null files, and the pairs.
#include <string>

#include "montecarlo/records/gap/diagnosis.h"
#include "montecarlo/report/json.h"

namespace insmc::gap {

/// Adds ml_parameters, heldout_loglik_gain(_per_run), null_loglik_gain and
/// ml_evaluations to a ranking entry (null gains and no parameters when the
/// candidate was not fitted).
void add_likelihood_json(mc::Json& entry, const LikelihoodResult& r, int runs);

/// The top-level pairs[].
mc::Json pairs_json(const Diagnosis& d);

/// gap.md's "maximum likelihood" table and the pairs' table (empty when nothing was fitted).
std::string likelihood_markdown(const Diagnosis& d);

}  // namespace insmc::gap
