#pragma once
/// Records far beyond anything the model gives: a corrupt value or a jump
/// in the logger. One such row of the test run (500 m on a position the
/// model knows to a few metres) scatters its run's fit and was named an
/// effect by the ranking; it is said first, as what it is.
///
/// A run is listed, with its largest row, when a row's normalized residual
/// z (run_analysis.h: unit variance under the model) exceeds both the Gaussian bound of every row
/// of the records at alpha (Bonferroni, |z| > Φ⁻¹(1 − alpha / (2 rows)))
/// and twice the largest |z| of the null runs (truth-level runs at the
/// records' times, ten times as many rows: what the model's own tails
/// give, quantization and resolution included), in at most a tenth of the
/// runs (Outliers::isolated).
#include <Eigen/Core>
#include <optional>
#include <vector>

#include "montecarlo/records/gap/diagnosis_results.h"
#include "montecarlo/records/runs/model/run_analysis.h"
#include "montecarlo/records/runs/prepared_runs.h"

namespace insmc::gap {

Outliers find_outliers(const runs::PreparedRuns& p, const std::vector<std::optional<runs::RunAnalyser>>& analysers,
                       const std::vector<Eigen::VectorXd>& null_z, double alpha);

/// "3 runs have a record beyond 5.5 σ of the model (the largest: run 7 at
/// t = 120 s, r_x, 1.6e+03 σ): ...", or "" unless isolated.
std::string outliers_sentence(const Outliers& o);

}  // namespace insmc::gap
