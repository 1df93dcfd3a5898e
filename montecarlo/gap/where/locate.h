#pragma once
/// Where one diagnosis' gap lies, assembled, from the pieces of
/// where.h (groups, shares, time functions, Allan curves).
#include <Eigen/Dense>
#include <optional>
#include <vector>

#include "montecarlo/gap/diagnosis.h"
#include "montecarlo/gap/fit/candidate_fit.h"
#include "montecarlo/gap/null/null_calibration.h"

namespace insmc::mc {

/// Fills d's groups, shares, time functions and Allan curves (and where
/// a pessimistic finding lies). `analysers` are the base model's per layout;
/// `null_z` and `null_layout` the null runs' row values and layouts.
void locate_gap(Diagnosis& d, const PreparedRuns& p, const std::vector<std::optional<gap::RunAnalyser>>& analysers,
                const gap::Pooled& observed, const Null& null, const std::vector<Eigen::VectorXd>& null_z,
                const std::vector<int>& null_layout, double alpha);

}  // namespace insmc::mc
