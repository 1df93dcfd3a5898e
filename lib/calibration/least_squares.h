#pragma once
/// Small nonlinear least squares for the calibrations of this folder:
/// Levenberg–Marquardt on a central-difference Jacobian, with the
/// parameters' covariance from the residual scatter and each parameter's
/// variance inflation (how much of its column the other columns explain).
#include <cstddef>
#include <functional>

#include <Eigen/Dense>

namespace insmc::calibration {

/// Writes the residuals at x into r (r has the size given to the fit).
using ResidualFunction = std::function<void(const Eigen::VectorXd& x, Eigen::VectorXd& r)>;

struct LeastSquaresFit {
  Eigen::VectorXd x;           ///< the estimate
  Eigen::MatrixXd covariance;  ///< σ̂² (JᵀJ)⁻¹; +inf on the diagonal where a parameter is not determined
  Eigen::VectorXd vif;         ///< variance inflation factor of each parameter (1: orthogonal to the rest; +inf: not separable)
  double residual_rms = 0;     ///< σ̂ = √(RSS / dof)
  int dof = 0;                 ///< residuals − parameters
  int iterations = 0;
  bool converged = false;
};

/// A parameter counts as separated from the others when its variance
/// inflation is at most this (the other columns explain at most 99 % of
/// its own); the project's choice, beside the usual warning level of 10.
inline constexpr double kMaxSeparableVif = 100.0;

/// Fits `residuals` (m of them, m > x0.size()) from x0; `step` is each
/// parameter's difference step (its scale). At most 100 iterations.
LeastSquaresFit fit_least_squares(const ResidualFunction& residuals, const Eigen::VectorXd& x0, std::size_t m,
                                  const Eigen::VectorXd& step);

/// Two-sided interval half-width factor at `confidence` for `dof` degrees of
/// freedom (Student's t; the residual scatter is itself estimated).
double t_factor(double confidence, int dof);

}  // namespace insmc::calibration
