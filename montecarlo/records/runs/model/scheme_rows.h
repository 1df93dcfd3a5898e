#pragma once
/// Records after a compensation scheme (docs/records.md: the header's scheme):
/// what the diagnosis' run model takes from chapter 5.
///
/// The scheme's position maps (compensation_maps.h, linear level) give each
/// r row after the scheme as a linear map of x, of a realignment's fresh
/// draws (ζ_r, ∂f_r, (u)V) and of what the test run or the alignment
/// produced. The test-run estimates (Û2, Û3 from position data (4.8), Û3
/// and Δf̂(T) from the accelerometer data (5.10), (5.12)) are recomputed from
/// each record's own test rows by the report's estimators, with the terms
/// `insmc run` fits, and their contribution is taken off that run's
/// navigation rows: exact, whatever unmodelled effect moved them. The
/// position estimator's input is Δr = r − r(0), and r(0) (the initial
/// position error at the position computer's resolution) is no row of a
/// record: its part stays in the model, a map of x and a rounding column.
/// 5.4's alignment-phase measurements are not in records either: they enter
/// as their maps of x (5.14), (5.19) and their counting noise.
///
/// What is not modelled after a scheme is left out of the rows
/// (layout.h): f rows after 5.4 and after a realignment (the torquers turn
/// the platform); after 5.2 and 5.3 the instruments go on as before.
#include <Eigen/Core>
#include <optional>
#include <vector>

#include "lib/preflight/test_run.h"
#include "lib/uncertainty/uncertainty_vector.h"
#include "montecarlo/records/runs/files/layout.h"

namespace insmc::runs {

/// Û2, Û3 (position data), Û3 (accelerometer data), Δf̂(T), per axis.
inline constexpr int kEstimateCount = 12;
using SchemeEstimates = Eigen::Matrix<double, kEstimateCount, 1>;

/// The scheme's part of a layout's base model.
struct SchemeRows {
  /// Rows whose x map the scheme replaces (r rows after it; every r row
  /// after 5.4, which acts from switch-over), and the replacement (rows × 33).
  std::vector<bool> replaced;
  Eigen::MatrixXd x_columns;
  /// Further causes: fresh draws of a realignment (their prior is that of
  /// the x slot `x_index`), the rounding of r(0) and 5.4's counting noise
  /// (x_index −1: prior `variance`).
  Eigen::MatrixXd columns;
  std::vector<int> x_index;
  Eigen::VectorXd variance;
  /// Rows × 12: what the test-run estimates add to each row (zero where the
  /// scheme does not use them).
  Eigen::MatrixXd estimate_map;
};

/// The test run's settings a scheme's estimators follow (T, τ, pulses,
/// resolution; the rest the report's defaults).
TestRunOptions record_test_options(const RecordSite& site);

SchemeRows scheme_rows(const Layout& layout, const RecordSite& site, const TestRunEstimators& estimators);

/// The estimates of a run from its test rows: f and r at every t_k = kτ,
/// k = 1..K, are needed (the data the scheme's estimates used); nullopt
/// when a row or a component is missing.
std::optional<SchemeEstimates> record_estimates(const RecordRun& run, const RecordSite& site,
                                                const TestRunEstimators& estimators);

}  // namespace insmc::runs
