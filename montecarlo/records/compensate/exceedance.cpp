#include "montecarlo/records/compensate/exceedance.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

#include "lib/common/assert.h"

namespace insmc::compensate {
namespace {

double normal_cdf(double z) { return 0.5 * std::erfc(-z / std::sqrt(2.0)); }

/// P(lo < p < hi) for p ~ N(m, s²); s = 0: a point at m.
double normal_interval(double m, double s, double lo, double hi) {
  if (!(s > 0)) return (m > lo && m < hi) ? 1.0 : 0.0;
  return std::max(0.0, normal_cdf((hi - m) / s) - normal_cdf((lo - m) / s));
}

}  // namespace

double probability_beyond(double mean, double variance, double limit) {
  INSMC_ASSERT(variance >= 0 && limit >= 0, "variance {} limit {}", variance, limit);
  return 1.0 - normal_interval(mean, std::sqrt(variance), -limit, limit);
}

double probability_outside_circle(const Eigen::Vector2d& mean, const Eigen::Matrix2d& covariance, double radius) {
  INSMC_ASSERT(radius >= 0, "radius {}", radius);
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(covariance);
  // Principal axes, the wider one outside: the inner integral is then the
  // narrower normal's interval probability, exact for any width.
  const Eigen::Vector2d var = eig.eigenvalues().cwiseMax(0.0);
  const Eigen::Vector2d m = eig.eigenvectors().transpose() * mean;
  const int outer = var[1] >= var[0] ? 1 : 0, inner = 1 - outer;
  const double s1 = std::sqrt(var[outer]), s2 = std::sqrt(var[inner]), m1 = m[outer], m2 = m[inner];
  const auto inside_at = [&](double p1) {
    const double h = std::sqrt(std::max(0.0, radius * radius - p1 * p1));
    return normal_interval(m2, s2, -h, h);
  };
  if (!(s1 > 0)) return 1.0 - (std::abs(m1) < radius ? inside_at(m1) : 0.0);
  // ∫ φ((p1 − m1)/s1)/s1 · P(|p2| < √(R² − p1²)) dp1 over |p1| < R, on the
  // part within 12 s1 of m1 (the rest weighs < 1e-30), composite Simpson
  // in the standardized variable; the chord's square root has an infinite
  // slope at ±R, so the grid is fine (4000 panels).
  const double lo = std::max(-radius, m1 - 12 * s1), hi = std::min(radius, m1 + 12 * s1);
  if (!(hi > lo)) return 1.0;
  // Substitute p1 = R sin θ where the range reaches ±R: smooth there.
  const double a = std::asin(std::clamp(lo / std::max(radius, 1e-300), -1.0, 1.0));
  const double b = std::asin(std::clamp(hi / std::max(radius, 1e-300), -1.0, 1.0));
  constexpr int kPanels = 4000;
  const double h = (b - a) / kPanels;
  double sum = 0.0;
  for (int i = 0; i <= kPanels; ++i) {
    const double theta = a + i * h;
    const double p1 = radius * std::sin(theta);
    const double z = (p1 - m1) / s1;
    const double f = std::exp(-0.5 * z * z) / (s1 * std::sqrt(2 * M_PI)) * inside_at(p1) * radius * std::cos(theta);
    sum += f * (i == 0 || i == kPanels ? 1.0 : i % 2 == 1 ? 4.0 : 2.0);
  }
  return std::clamp(1.0 - sum * h / 3.0, 0.0, 1.0);
}

}  // namespace insmc::compensate
