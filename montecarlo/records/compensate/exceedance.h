#pragma once
/// The probability that a Gaussian position error exceeds a limit: one
/// axis (|p| > L) or the horizontal (|p| > L for a 2-D p ~ N(m, C)), the
/// latter by quadrature over the principal axes (no sampling: the same
/// answer every run).
#include <Eigen/Core>

namespace insmc::compensate {

/// P(|p| > limit), p ~ N(mean, variance); variance ≥ 0.
double probability_beyond(double mean, double variance, double limit);

/// P(‖p‖ > radius), p ~ N(mean, covariance) in the plane; covariance
/// symmetric positive semi-definite. Accurate to 1e-9 absolute.
double probability_outside_circle(const Eigen::Vector2d& mean, const Eigen::Matrix2d& covariance, double radius);

}  // namespace insmc::compensate
