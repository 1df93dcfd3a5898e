#pragma once
/// Which effect the per-run estimates point to, when they stand beyond the
/// prior (where/estimate_test.h). Each candidate that acts inside the
/// model's parameter space (a deterministic signature the same in every
/// run, or priors widened) is carried through the test run's estimators:
/// its signature moves the estimates' mean by W μ per unit amplitude, its
/// widened priors add W H ΔP Hᵀ Wᵀ to their covariance (W the map from the
/// test rows to the normalized estimates, run_analysis.h). The estimates
/// of the runs are Gaussian about the null runs' mean with the null runs'
/// covariance plus that; each candidate is fitted on one half of the runs
/// (its grid, amplitudes by least squares) and scored on the other, by the
/// log-likelihood gain over the null (2-fold, summed).
#include <vector>

#include "montecarlo/records/gap/candidates/candidates.h"
#include "montecarlo/records/gap/diagnosis_results.h"
#include "montecarlo/records/gap/where/estimate_test.h"

namespace insmc::gap {

/// The candidates' held-out gains (descending) and the name they give:
/// the first, or the first two as a class when the runner-up is within
/// 1.92 nats (½ χ²₁ at 95 %) of it. Candidates with columns, row noise or
/// their own counting (random processes, quantization) act beyond the
/// estimates and are not scored here.
void name_from_estimates(EstimateTest& test, const RunEstimates& e, const runs::PreparedRuns& p,
                         const runs::RunAnalyser& analyser, int layout, const std::vector<Candidate>& candidates);

}  // namespace insmc::gap
