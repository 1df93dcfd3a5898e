// The misalignment's second order (montecarlo/records/gap/candidates/
// misalignment_second_order.h) against the rotation itself: misalignments
// drawn per axis, each turning f by the exact rotation (Eigen's angle-axis),
// the first order taken off. The remainder's sample mean and covariance must
// be the terms' mean and Σ_c var_c B_c B_cᵀ within their Monte Carlo error.
#include "montecarlo/records/gap/candidates/misalignment_second_order.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "tests/unit/montecarlo/records/runs/test_layout.h"

namespace insmc::gap::candidates {
namespace {

/// The remainder R f − f − φ × f over `draws` misalignments φ = D z, against
/// the terms' mean and covariance: every mean and covariance entry within 5
/// of its Monte Carlo standard errors (from the sample's own moments: a
/// fixed seed, a bound of the statistic, not a tuned tolerance), plus 0.2 %
/// of the entry's scale for the third order (odd in z, of relative size
/// |φ|² ≈ 1e-3 here).
void expect_rotation_moments(const Eigen::Vector3d& f, const Eigen::Vector3d& sigma, std::uint64_t seed) {
  const Eigen::Matrix<double, 3, 6> B = second_order_unit_terms(f);
  const SecondOrderWeights w = second_order_weights(sigma);
  const Eigen::Vector3d mean = B * w.mean;
  const Eigen::Matrix3d cov = B * w.variance.asDiagonal() * B.transpose();

  constexpr int kDraws = 400'000;
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> normal;
  std::vector<Eigen::Vector3d> remainders;
  remainders.reserve(kDraws);
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (int k = 0; k < kDraws; ++k) {
    const Eigen::Vector3d phi(sigma[0] * normal(rng), sigma[1] * normal(rng), sigma[2] * normal(rng));
    const Eigen::Matrix3d R = Eigen::AngleAxisd(phi.norm(), phi.normalized()).toRotationMatrix();
    remainders.push_back(R * f - f - phi.cross(f));
    sum += remainders.back();
  }
  const Eigen::Vector3d sample_mean = sum / kDraws;
  Eigen::Matrix3d sample_cov = Eigen::Matrix3d::Zero(), products_sq = Eigen::Matrix3d::Zero();
  for (const Eigen::Vector3d& x : remainders) {
    const Eigen::Vector3d d = x - sample_mean;
    const Eigen::Matrix3d outer = d * d.transpose();
    sample_cov += outer;
    products_sq += outer.cwiseProduct(outer);
  }
  sample_cov /= kDraws - 1;
  products_sq /= kDraws;
  const double scale = std::sqrt(cov.diagonal().maxCoeff());
  for (int i = 0; i < 3; ++i) {
    const double se_mean = std::sqrt(sample_cov(i, i) / kDraws);
    EXPECT_NEAR(sample_mean[i], mean[i], 5 * se_mean + 2e-3 * scale) << "mean, axis " << i;
    for (int j = 0; j <= i; ++j) {
      // The standard error of a sample covariance: sqrt((E[d_i² d_j²] − cov²)/n).
      const double se = std::sqrt((products_sq(i, j) - sample_cov(i, j) * sample_cov(i, j)) / kDraws);
      EXPECT_NEAR(sample_cov(i, j), cov(i, j), 5 * se + 2e-3 * scale * scale) << "covariance " << i << j;
    }
  }
}

TEST(MisalignmentSecondOrder, MeanAndCovarianceAreTheExactRotationsToTheirMonteCarloError) {
  // A specific force with gravity partly horizontal (the platform after an
  // hour and a half in a': gravity has turned in it by about 20°).
  const Eigen::Vector3d f(2.1, -2.6, 9.3);
  // alignment_transient at 30 times its default: a level of 1 mrad, an azimuth of 30 mrad.
  expect_rotation_moments(f, Eigen::Vector3d(1e-3, 1e-3, 30e-3), 11);
  // switch_transient's misalignment, the same on every axis (10 mrad): every
  // term of the same size, the products' signs seen in every covariance.
  expect_rotation_moments(f, Eigen::Vector3d::Constant(10e-3), 12);
  // Not trivial: the mean is a sizeable part of the spread (the runs share it).
  const SecondOrderWeights w = second_order_weights(Eigen::Vector3d(1e-3, 1e-3, 30e-3));
  const Eigen::Matrix<double, 3, 6> B = second_order_unit_terms(f);
  const Eigen::Matrix3d cov = B * w.variance.asDiagonal() * B.transpose();
  EXPECT_GT((B * w.mean).head<2>().norm(), 0.3 * std::sqrt(cov(0, 0) + cov(1, 1)));
}

TEST(MisalignmentSecondOrder, ARealignmentDrawsTheSpreadAnewAndKeepsTheMean) {
  const runs::RecordSite site = runs::testing::test_site();
  const auto second_order = [&](const runs::Layout& l) {
    runs::Extension e;
    add_misalignment_second_order({&l, &site, nullptr, {}}, Eigen::Vector3d::Constant(10e-3), e);
    return e;
  };
  const runs::Layout one = runs::testing::test_layout(2700.0);
  runs::Layout realigned = one;
  realigned.nav = runs::NavSegment::kRestart;
  realigned.nav_start_s = 900.0;  // the second switch-over at the test run's end
  const runs::Extension a = second_order(one), b = second_order(realigned);
  EXPECT_TRUE(a.columns_higher_order && b.columns_higher_order);
  ASSERT_EQ(a.columns.cols(), 6);
  ASSERT_EQ(b.columns.cols(), 12);
  const Eigen::Index n = b.columns.rows(), nt = realigned.test_rows;
  // The test run's spread and the realigned navigation's: no column in both.
  EXPECT_EQ(b.columns.topRightCorner(nt, 6).norm(), 0.0);
  EXPECT_EQ(b.columns.bottomLeftCorner(n - nt, 6).norm(), 0.0);
  EXPECT_GT(b.columns.topLeftCorner(nt, 6).norm(), 0.0);
  EXPECT_GT(b.columns.bottomRightCorner(n - nt, 6).norm(), 0.0);
  EXPECT_EQ(b.column_var.head(6), b.column_var.tail(6));
  // Without the realignment the navigation's columns are the test run's.
  EXPECT_GT(a.columns.bottomRows(n - nt).norm(), 0.0);
  EXPECT_GT(b.mean.tail(n - nt).norm(), 0.0);
}

TEST(MisalignmentSecondOrder, ANoMisalignmentHasNoSecondOrder) {
  const SecondOrderWeights w = second_order_weights(Eigen::Vector3d::Zero());
  EXPECT_EQ(w.mean.norm(), 0.0);
  EXPECT_EQ(w.variance.norm(), 0.0);
}

}  // namespace
}  // namespace insmc::gap::candidates
