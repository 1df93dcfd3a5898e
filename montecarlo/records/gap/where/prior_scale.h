#pragma once
/// When the model is pessimistic about the runs: would priors narrower than
/// Table 3.1 account for it? Every prior variance is scaled by s² (the
/// `bounds` candidate's extension, here from 0.01 to 100 rather than from
/// 1.5 up: below 1 the priors are wider than this system), s chosen by least
/// G over all runs on a log grid of step 10^(1/8) ≈ ×1.33, with the
/// 16–84 % range of 200 resampled fits. G₋ left at that s says whether the
/// priors explain the pessimism or another assumption does (a declared pulse
/// weight or resolution coarser than the data). It is a finding, not an
/// effect: it never enters the ranking or the greedy steps.
#include <cstdint>

#include "montecarlo/records/gap/diagnosis_results.h"
#include "montecarlo/records/runs/prepared_runs.h"

namespace insmc::gap {

/// `pessimistic_critical`: the null files' G₋ critical value (critical_value).
PriorScale fit_prior_scale(const runs::PreparedRuns& p, const NullCalibration& m0, double pessimistic_critical,
                           std::uint64_t seed);

}  // namespace insmc::gap
