#pragma once
/// How well a stationary test run determines the estimates the compensation
/// schemes use, before any data are seen: each estimate of apply_estimators
/// (test_run.h; Û2, Û3 of (4.8b, c), the accelerometer slope Û3 of (4.4),
/// (5.12), Δf̂(T) of (5.10)) less what it estimates (U2, U3 of (3.29b, c),
/// the accelerometer output error at T) is a linear map of the
/// uncertainties x plus the instruments' quantization (instruments.h): the
/// position readout's rounding e_k − e_0 (each uniform, variance q²/12) and
/// the ΔV counter's remainders (U_{k−1} − U_k)/τ (each uniform, variance
/// w²/12). Under an uncertainty model the errors then have an exact mean and
/// covariance (the remainders taken independent, as they are once the
/// pulses per interval are many and irregular).
#include <array>

#include "lib/preflight/test_run.h"

namespace insmc {

struct EstimateErrors {
  /// Per axis: error of each estimate row (EstimateRow) per unit of x.
  std::array<Eigen::Matrix<double, kEstimateRows, ux::kDim>, 3> x_map;
  /// Per axis: covariance of the estimate rows from the quantization alone.
  std::array<Eigen::Matrix<double, kEstimateRows, kEstimateRows>, 3> noise_covariance;
  /// Per axis: mean and covariance of the errors under the uncertainty model.
  std::array<Eigen::Matrix<double, kEstimateRows, 1>, 3> mean;
  std::array<Eigen::Matrix<double, kEstimateRows, kEstimateRows>, 3> covariance;
};

/// The targets are the `paper` level's U2, U3 (3.29b, c) and the model's own
/// accelerometer output error at T (4.4): at the linear level the
/// estimators' truth is the report's definition of what they estimate.
EstimateErrors estimate_errors(System system, Fidelity fidelity, const ModelOptions& model, const TestRunOptions& test,
                               const TestRunEstimators& estimators, const UncertaintyModel& uncertainties);

}  // namespace insmc
