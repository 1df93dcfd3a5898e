#pragma once
/// `insmc gap`: the sim-to-real gap diagnosis of record files (docs/gap.md,
/// docs/records.md).
///
/// 1. Model: each run's f and r rows as the linear level predicts them
///    (model/), the test run fitted, the navigation predicted from the fit.
/// 2. Gap: G of metric/gap_metric.h on all runs, against the model's own
///    null: truth-level runs with no effect and the priors, simulated at the
///    records' own times, pulse weight, resolution, latitude and system
///    (record_simulation.h). Significance: the share of null files (runs drawn
///    with replacement from the null runs, as many as the records have) whose
///    G is at least the observed one.
/// 3. Where: each group's ℓ_g and its own null p-value, shares of Σ ℓ_g² by
///    axis, stage and window; the post-test innovations projected on the time
///    functions of the error (Schuler, earth rate, t², t³, t⁴); the Allan
///    deviation of the f residuals against the null's.
/// 4. Which effect: every candidate (candidates/candidates.h) fitted on one half
///    of the runs (grid search, least G), scored on the other half, and the
///    halves swapped (2-fold cross-validation): ranked by held-out G. The
///    first few also fitted by maximum likelihood between physical limits
///    (ranking/likelihood_ranking.h), beside the ranking.
/// 5. How far: shrink = 1 − G_after/G_before on held-out runs; effects added
///    greedily while the held-out gap stays significant.
/// The diagnosis reads only the records' non-`truth.` keys and the priors.
#include "lib/records/record.h"
#include "montecarlo/records/gap/diagnosis_options.h"
#include "montecarlo/records/gap/diagnosis_results.h"

namespace insmc::gap {

/// Diagnoses the runs of one record file (already read and validated).
/// Throws InputError when the file cannot be diagnosed at all (e.g. no run
/// with test rows).
Diagnosis diagnose(const RecordFile& file, const DiagnosisOptions& options);

}  // namespace insmc::gap
