// The Gaussian CEP of `insmc covariance` (montecarlo/study/aggregate/gaussian_cep.h)
// against closed forms (circular: R = σ√(−2 ln(1 − p)); a line: the
// half-normal quantile) and against a sampled ellipse with a mean, whose
// hit count at the computed radius is binomial.
#include <gtest/gtest.h>

#include <Eigen/Cholesky>

#include <cmath>
#include <random>

#include "montecarlo/study/aggregate/gaussian_cep.h"
#include "tests/ordered_draws.h"

namespace insmc::mc {
namespace {

TEST(GaussianCep, CircularIsTheRayleighQuantile) {
  const double sigma = 250.0;
  const Eigen::Matrix2d p = sigma * sigma * Eigen::Matrix2d::Identity();
  for (const double q : {0.5, 0.95})
    EXPECT_NEAR(gaussian_cep(Eigen::Vector2d::Zero(), p, q), sigma * std::sqrt(-2 * std::log(1 - q)), 1e-6 * sigma) << q;
  EXPECT_NEAR(gaussian_probability_within(Eigen::Vector2d::Zero(), p, sigma), 1 - std::exp(-0.5), 1e-9);
}

TEST(GaussianCep, AnErrorAlongOneLineIsTheHalfNormalQuantile) {
  Eigen::Matrix2d p = Eigen::Matrix2d::Zero();
  p(0, 0) = p(1, 1) = 0.5;  // variance 1 along (1, 1)/√2
  p(0, 1) = p(1, 0) = 0.5;
  EXPECT_NEAR(gaussian_cep(Eigen::Vector2d::Zero(), p, 0.5), 0.6744897501960817, 1e-7);
  EXPECT_NEAR(gaussian_cep(Eigen::Vector2d::Zero(), p, 0.95), 1.959963984540054, 1e-7);
  EXPECT_EQ(gaussian_cep(Eigen::Vector2d::Zero(), Eigen::Matrix2d::Zero(), 0.5), 0.0);
  EXPECT_NEAR(gaussian_cep(Eigen::Vector2d(3, 4), Eigen::Matrix2d::Zero(), 0.5), 5.0, 1e-8);
  // A line off the origin: e = (u, 3) with u ~ N(0, 1): |e| ≤ R where |u| ≤ √(R² − 9).
  Eigen::Matrix2d along_x = Eigen::Matrix2d::Zero();
  along_x(0, 0) = 1;
  EXPECT_NEAR(gaussian_cep(Eigen::Vector2d(0, 3), along_x, 0.5), std::hypot(3.0, 0.6744897501960817), 1e-7);
}

TEST(GaussianCep, AShiftedEllipseHoldsItsShareOfSamples) {
  const Eigen::Vector2d mean(400, -150);
  Eigen::Matrix2d p;
  p << 300 * 300, 0.6 * 300 * 120, 0.6 * 300 * 120, 120 * 120;
  const Eigen::LLT<Eigen::Matrix2d> llt(p);
  std::mt19937_64 rng(20261126);
  std::normal_distribution<double> n01;
  constexpr int kSamples = 200000;
  for (const double q : {0.5, 0.95}) {
    const double r = gaussian_cep(mean, p, q);
    int inside = 0;
    for (int i = 0; i < kSamples; ++i) {
      const auto z = insmc::testing::ordered_draws<2>(n01, rng);
      const Eigen::Vector2d e = mean + llt.matrixL() * Eigen::Vector2d(z[0], z[1]);
      inside += e.norm() <= r;
    }
    // Binomial(kSamples, q): 4.5 standard deviations (a fixed seed; about
    // 7e-6 two-sided for a correct radius).
    const double sd = std::sqrt(kSamples * q * (1 - q));
    EXPECT_NEAR(inside, kSamples * q, 4.5 * sd) << q << " radius " << r;
  }
}

}  // namespace
}  // namespace insmc::mc
