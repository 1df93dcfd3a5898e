#include "montecarlo/study/aggregate/gaussian_cep.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <numbers>

#include "lib/common/assert.h"

namespace insmc::mc {
namespace {

double normal_cdf(double z) { return 0.5 * std::erfc(-z / std::numbers::sqrt2); }

/// The probability that a normal variable (mean m, deviation s ≥ 0) lies
/// in [a, b]; a step when s = 0.
double normal_between(double m, double s, double a, double b) {
  if (s <= 0) return m >= a && m <= b ? 1.0 : 0.0;
  return normal_cdf((b - m) / s) - normal_cdf((a - m) / s);
}

}  // namespace

double gaussian_probability_within(const Eigen::Vector2d& mean, const Eigen::Matrix2d& covariance, double radius) {
  if (!(radius > 0)) return 0.0;
  // Principal axes: u = Qᵀ e has independent components with variances λ.
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(0.5 * (covariance + covariance.transpose()));
  const Eigen::Vector2d lambda = eig.eigenvalues().cwiseMax(0.0);
  const Eigen::Vector2d m = eig.eigenvectors().transpose() * mean;
  const double s1 = std::sqrt(lambda[1]), s2 = std::sqrt(lambda[0]);  // s1 ≥ s2
  const double m1 = m[1], m2 = m[0];
  // P = ∫ over u1 = R sin θ, θ ∈ [−π/2, π/2], of the density of u1 times
  // P(|u2| ≤ R cos θ): smooth in θ (the √(R² − u1²) edge is gone).
  // With s1 = 0 both components are points.
  if (s1 <= 0) return std::hypot(m1, m2) <= radius ? 1.0 : 0.0;
  // A line (s2 = 0): u2 = m2 exactly, so |e| ≤ R where |u1| ≤ √(R² − m2²).
  if (s2 <= 0) {
    if (std::abs(m2) > radius) return 0.0;
    const double half = std::sqrt(radius * radius - m2 * m2);
    return normal_between(m1, s1, -half, half);
  }
  constexpr int kIntervals = 2000;  // even, for Simpson's rule
  const double h = std::numbers::pi / kIntervals;
  double sum = 0;
  for (int i = 0; i <= kIntervals; ++i) {
    const double theta = -std::numbers::pi / 2 + i * h;
    const double u1 = radius * std::sin(theta), half_chord = radius * std::cos(theta);
    const double z = (u1 - m1) / s1;
    const double density = std::exp(-0.5 * z * z) / (s1 * std::sqrt(2 * std::numbers::pi));
    const double f = density * normal_between(m2, s2, -half_chord, half_chord) * radius * std::cos(theta);
    sum += f * (i == 0 || i == kIntervals ? 1 : i % 2 ? 4 : 2);
  }
  return std::clamp(sum * h / 3, 0.0, 1.0);
}

double gaussian_cep(const Eigen::Vector2d& mean, const Eigen::Matrix2d& covariance, double p) {
  INSMC_ASSERT(p > 0 && p < 1, "CEP probability {} outside (0, 1)", p);
  const double scale = std::sqrt(mean.squaredNorm() + std::max(0.0, covariance.trace()));
  if (!(scale > 0)) return 0.0;
  // P(|e| ≤ R) rises from 0 to 1; R lies within [0, |mean| + 40 σ_max].
  double lo = 0, hi = mean.norm() + 40 * std::sqrt(std::max(0.0, covariance.trace()));
  for (int step = 0; step < 200 && hi - lo > 1e-10 * scale; ++step) {
    const double mid = 0.5 * (lo + hi);
    (gaussian_probability_within(mean, covariance, mid) < p ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace insmc::mc
