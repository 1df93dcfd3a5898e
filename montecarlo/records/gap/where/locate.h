#pragma once
/// Where one diagnosis' gap lies, assembled, from the pieces of
/// where.h (groups, shares, time functions, Allan curves).
#include <Eigen/Dense>
#include <optional>
#include <string>
#include <vector>

#include "montecarlo/records/gap/diagnosis_results.h"
#include "montecarlo/records/runs/prepared_runs.h"
#include "montecarlo/records/gap/null/null_calibration.h"

namespace insmc::gap {

/// The null runs with the sensor's own noise through the import
/// (null/import_null.h), as locate_gap draws their bands beside the model's.
struct OwnNoiseRuns {
  std::vector<LogRatios> log_ratios;  ///< its null files read with the model's expectations
  std::vector<Eigen::VectorXd> z;     ///< each null run's row values under the base model
  std::vector<int> layout_of;         ///< and its layout
};

/// The groups, their shares, the time functions and the Allan curves of
/// the `observed` runs (and, when `pessimistic_significant`, the groups a
/// pessimistic finding lies in). `analysers` are the base model's per layout;
/// `null_z` and `null_layout` the null runs' row values and layouts. With
/// `own_noise`, every group and Allan point also gets the band the sensor's
/// own noise through the import puts it in.
GapLocation locate_gap(const runs::PreparedRuns& p, const std::vector<std::optional<runs::RunAnalyser>>& analysers,
                       const Pooled& observed, const ModelNull& null, const std::vector<Eigen::VectorXd>& null_z,
                       const std::vector<int>& null_layout, double alpha, bool pessimistic_significant,
                       const OwnNoiseRuns* own_noise = nullptr);

}  // namespace insmc::gap
