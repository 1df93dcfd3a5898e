#pragma once
/// The circular error probable of a horizontal error taken as Gaussian with
/// a given mean and 2×2 covariance: the radius R with P(|e| ≤ R) = p. Used
/// by `insmc covariance`, whose moments are exact for the linear model but
/// whose distribution is not known (the inputs are uniform): the CEP there is
/// the Gaussian one with those moments, and says so. The Monte Carlo gets its
/// CEP from the samples instead (horizontal_accuracy.h).
#include <Eigen/Core>

namespace insmc::mc {

/// P(|e| ≤ radius) for e ~ N(mean, covariance) in the plane. Exact to about
/// 1e-9 (Simpson's rule over the circle after turning to the principal axes).
double gaussian_probability_within(const Eigen::Vector2d& mean, const Eigen::Matrix2d& covariance, double radius);

/// The radius with P(|e| ≤ R) = p, 0 < p < 1 (bisection to 1e-10 relative).
/// 0 when the error is exactly 0.
double gaussian_cep(const Eigen::Vector2d& mean, const Eigen::Matrix2d& covariance, double p);

}  // namespace insmc::mc
