#pragma once
/// The evaluation a likelihood fit (likelihood_fit.h) injects for a
/// candidate effect: at given values of its non-amplitude parameters, the
/// candidate's extension built for every layout on top of the effects
/// already selected, combined with the layout's base model (gaussian_model.h),
/// factorized once (model/likelihood.h), and every run's exact
/// log-likelihood. Amplitude parameters are held at given values, 0 unless
/// told (their signature is a mean; its least-squares fit stays in
/// candidate_fit.h). Several candidates together are one joint evaluation:
/// their extensions all added, their parameters one after the other.
#include <vector>

#include "montecarlo/records/gap/candidates/candidates.h"
#include "montecarlo/records/gap/fit/candidate_fit.h"
#include "montecarlo/records/gap/fit/likelihood_lattice.h"

namespace insmc::gap {

/// Indices (in c.parameters) of the parameters a likelihood fit searches:
/// the non-amplitude ones, in order. The evaluation takes values in this order.
std::vector<int> likelihood_parameters(const Candidate& c);

/// The per-run log-likelihoods of `p`'s runs under `c` at the values of
/// likelihood_parameters(c), on top of `selected` (per layout). `p`, `c` and
/// `selected` must outlive the returned function.
RunLogLikelihoods candidate_evaluation(const runs::PreparedRuns& p, const Candidate& c,
                                       const std::vector<std::vector<runs::Extension>>& selected);

/// A candidate in a joint evaluation: its amplitudes (amplitude_indices()
/// order; empty: all 0) held at these values.
struct HeldCandidate {
  const Candidate* candidate = nullptr;
  std::vector<double> amplitudes;
};

/// The per-run log-likelihoods of `p`'s runs with every candidate of
/// `candidates` added on top of `selected`, at the values of each one's
/// likelihood_parameters() in turn. `p`, the candidates and `selected` must
/// outlive the returned function.
RunLogLikelihoods joint_evaluation(const runs::PreparedRuns& p, std::vector<HeldCandidate> candidates,
                                   const std::vector<std::vector<runs::Extension>>& selected);

/// The per-run log-likelihoods under the selected effects alone (the null of
/// the cross-validation gain).
std::vector<double> null_log_likelihoods(const runs::PreparedRuns& p,
                                         const std::vector<std::vector<runs::Extension>>& selected);

}  // namespace insmc::gap
