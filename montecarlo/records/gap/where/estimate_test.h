#pragma once
/// The per-run estimates against the prior (docs/gap-method.md §2, "Effects
/// inside the priors"). An effect that stays inside the model's own
/// parameter space (a step at switch-over, a drift shared by every run)
/// leaves the rows' scatter as the model predicts it and shows only in the
/// test run's estimates ĉ of Table 3.1's x: runs beyond the reach of the
/// prior, a spread wider than the prior's, a mean over the runs away from
/// zero. The null is the calibration's truth runs (x drawn from Table
/// 3.1's uniform bounds, through the same estimators), pooled into the same
/// bootstrap null files as G (null/bootstrap.h), so the table's least p and
/// G₊'s p are read jointly against those files.
#include <vector>

#include "montecarlo/records/gap/diagnosis_options.h"
#include "montecarlo/records/gap/diagnosis_results.h"
#include "montecarlo/records/gap/null/null_calibration.h"
#include "montecarlo/records/runs/model/run_analysis.h"
#include "montecarlo/records/runs/prepared_runs.h"

namespace insmc::gap {

/// The normalized estimates of the x columns every layout resolves
/// (`columns`, catalogue indices), one column per run.
struct RunEstimates {
  std::vector<int> columns;
  Eigen::MatrixXd records;  ///< columns × record runs
  Eigen::MatrixXd null;     ///< columns × null runs
};
RunEstimates run_estimates(const runs::PreparedRuns& p, const std::vector<const runs::RunAnalyser*>& analysers,
                           const ModelNull& null);

/// The table and its significance; `unmodelled_p` is G₊'s p (against
/// null.unmodelled, whose bootstrap files this test reuses).
EstimateTest test_estimates(const RunEstimates& e, const ModelNull& null, const DiagnosisOptions& options,
                            double unmodelled_p);

}  // namespace insmc::gap
