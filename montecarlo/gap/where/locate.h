#pragma once
/// Where one diagnosis' gap lies, assembled, from the pieces of
/// where.h (groups, shares, time functions, Allan curves).
#include <Eigen/Dense>
#include <optional>
#include <vector>

#include "montecarlo/gap/diagnosis_results.h"
#include "montecarlo/runs/prepared_runs.h"
#include "montecarlo/gap/null/null_calibration.h"

namespace insmc::gap {

/// Fills d's groups, shares, time functions and Allan curves (and where
/// a pessimistic finding lies). `analysers` are the base model's per layout;
/// `null_z` and `null_layout` the null runs' row values and layouts.
void locate_gap(Diagnosis& d, const runs::PreparedRuns& p, const std::vector<std::optional<runs::RunAnalyser>>& analysers,
                const Pooled& observed, const ModelNull& null, const std::vector<Eigen::VectorXd>& null_z,
                const std::vector<int>& null_layout, double alpha);

}  // namespace insmc::gap
