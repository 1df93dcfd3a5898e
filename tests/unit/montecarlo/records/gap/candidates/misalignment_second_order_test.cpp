// The misalignment's second order (montecarlo/records/gap/candidates/
// misalignment_second_order.h) against the rotation itself: misalignments
// drawn per axis, each turning f by the exact rotation (Eigen's angle-axis),
// the first order taken off. The remainder's sample mean and covariance must
// be the terms' mean and Σ_c var_c B_c B_cᵀ within their Monte Carlo error
// (the third order, odd in the draws, adds to the covariance only
// |φ|² ≈ 1e-3 of it at these angles).
#include "montecarlo/records/gap/candidates/misalignment_second_order.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace insmc::gap::candidates {
namespace {

TEST(MisalignmentSecondOrder, MeanAndCovarianceAreTheExactRotationsToTheirMonteCarloError) {
  // A specific force with gravity partly horizontal (the platform after an
  // hour and a half in a': gravity has turned in it by about 20°), and a
  // level of 1 mrad, an azimuth of 30 mrad (alignment_transient at 30 times
  // its default).
  const Eigen::Vector3d f(2.1, -2.6, 9.3);
  const Eigen::Vector3d sigma(1e-3, 1e-3, 30e-3);
  const Eigen::Matrix<double, 3, 6> B = second_order_unit_terms(f);
  const SecondOrderWeights w = second_order_weights(sigma);
  const Eigen::Vector3d mean = B * w.mean;
  const Eigen::Matrix3d cov = B * w.variance.asDiagonal() * B.transpose();

  constexpr int kDraws = 400'000;
  std::mt19937_64 rng(11);
  std::normal_distribution<double> normal;
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  Eigen::Matrix3d sum2 = Eigen::Matrix3d::Zero();
  Eigen::Vector3d fourth = Eigen::Vector3d::Zero();  // Σ (x − mean)⁴ per axis, for the variances' error
  std::vector<Eigen::Vector3d> remainders;
  remainders.reserve(kDraws);
  for (int k = 0; k < kDraws; ++k) {
    const Eigen::Vector3d phi(sigma[0] * normal(rng), sigma[1] * normal(rng), sigma[2] * normal(rng));
    const Eigen::Matrix3d R = Eigen::AngleAxisd(phi.norm(), phi.normalized()).toRotationMatrix();
    const Eigen::Vector3d x = R * f - f - phi.cross(f);
    remainders.push_back(x);
    sum += x;
  }
  const Eigen::Vector3d sample_mean = sum / kDraws;
  for (const Eigen::Vector3d& x : remainders) {
    const Eigen::Vector3d d = x - sample_mean;
    sum2 += d * d.transpose();
    fourth += d.array().pow(4).matrix();
  }
  const Eigen::Matrix3d sample_cov = sum2 / (kDraws - 1);
  for (int i = 0; i < 3; ++i) {
    // Mean: 5 standard errors (a fixed seed; the bound is the statistic's own).
    const double se_mean = std::sqrt(sample_cov(i, i) / kDraws);
    EXPECT_NEAR(sample_mean[i], mean[i], 5 * se_mean + 1e-12) << "axis " << i;
    // Variance: 5 standard errors of a sample variance, sqrt((m4 − s⁴)/n).
    const double m4 = fourth[i] / kDraws;
    const double se_var = std::sqrt((m4 - sample_cov(i, i) * sample_cov(i, i)) / kDraws);
    EXPECT_NEAR(sample_cov(i, i), cov(i, i), 5 * se_var + 2e-3 * cov(i, i)) << "axis " << i;
  }
  // The correlation between the horizontal axes, to 0.02.
  const double rho = sample_cov(0, 1) / std::sqrt(sample_cov(0, 0) * sample_cov(1, 1));
  const double rho_model = cov(0, 1) / std::sqrt(cov(0, 0) * cov(1, 1));
  EXPECT_NEAR(rho, rho_model, 0.02);
  // Not trivial: the mean is a sizeable part of the spread (the runs share it).
  EXPECT_GT(mean.head<2>().norm(), 0.3 * std::sqrt(cov(0, 0) + cov(1, 1)));
}

TEST(MisalignmentSecondOrder, ANoMisalignmentHasNoSecondOrder) {
  const SecondOrderWeights w = second_order_weights(Eigen::Vector3d::Zero());
  EXPECT_EQ(w.mean.norm(), 0.0);
  EXPECT_EQ(w.variance.norm(), 0.0);
}

}  // namespace
}  // namespace insmc::gap::candidates
