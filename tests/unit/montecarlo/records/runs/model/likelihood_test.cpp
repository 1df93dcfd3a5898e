// The exact Gaussian log-likelihood of a run (montecarlo/records/runs/model/likelihood.h):
// the O(n d²) determinant-lemma/Woodbury form against the dense formula, and
// −2 log p over draws from the model against its chi-square expectation.
#include "montecarlo/records/runs/model/likelihood.h"

#include <gtest/gtest.h>

#include <Eigen/Cholesky>
#include <cmath>
#include <numbers>
#include <random>

namespace insmc::runs {
namespace {

/// ~40 rows, 8 causes with priors spanning 1e-12..1e6 (one cause of prior 0,
/// dropped), noise of varied size; the mean nonzero.
GaussianModel random_model(std::mt19937_64& rng) {
  std::normal_distribution<double> normal;
  const int n = 40, d = 9;
  GaussianModel m;
  m.mean = Eigen::VectorXd::NullaryExpr(n, [&] { return normal(rng); });
  m.H = Eigen::MatrixXd::NullaryExpr(n, d, [&] { return normal(rng); });
  m.prior_var.resize(d);
  for (int j = 0; j < 8; ++j) m.prior_var[j] = std::pow(10.0, -12.0 + 18.0 * j / 7.0);
  m.prior_var[8] = 0.0;
  m.noise_var = Eigen::VectorXd::NullaryExpr(n, [&] { return std::exp(normal(rng)); });
  m.actual_noise_var = m.noise_var;
  return m;
}

double dense_log_likelihood(const GaussianModel& m, const Eigen::VectorXd& y) {
  const Eigen::MatrixXd S =
      m.H * m.prior_var.asDiagonal() * m.H.transpose() + Eigen::MatrixXd(m.noise_var.asDiagonal());
  const Eigen::LLT<Eigen::MatrixXd> llt(S);
  EXPECT_EQ(llt.info(), Eigen::Success);
  const Eigen::VectorXd r = y - m.mean;
  const double log_det = 2.0 * llt.matrixL().toDenseMatrix().diagonal().array().log().sum();
  const double n = static_cast<double>(y.size());
  return -0.5 * (n * std::log(2.0 * std::numbers::pi) + log_det + r.dot(llt.solve(r)));
}

/// A draw y = μ + H c + e from the model.
Eigen::VectorXd draw(const GaussianModel& m, std::mt19937_64& rng) {
  std::normal_distribution<double> normal;
  const Eigen::VectorXd c =
      m.prior_var.cwiseSqrt().cwiseProduct(Eigen::VectorXd::NullaryExpr(m.H.cols(), [&] { return normal(rng); }));
  const Eigen::VectorXd e =
      m.noise_var.cwiseSqrt().cwiseProduct(Eigen::VectorXd::NullaryExpr(m.H.rows(), [&] { return normal(rng); }));
  return m.mean + m.H * c + e;
}

TEST(GapLikelihood, AgreesWithTheDenseFormula) {
  std::mt19937_64 rng(7);
  for (int trial = 0; trial < 5; ++trial) {
    const GaussianModel m = random_model(rng);
    const RunLikelihood lik(m);
    for (int k = 0; k < 4; ++k) {
      // Draws from the model, and one far from it (a large quadratic term).
      const Eigen::VectorXd y = k < 3 ? draw(m, rng) : Eigen::VectorXd(m.mean + 1e3 * m.noise_var);
      const double dense = dense_log_likelihood(m, y), fast = lik.log_likelihood(y);
      EXPECT_NEAR(fast, dense, 1e-9 * std::abs(dense)) << "trial " << trial << " draw " << k;
    }
  }
}

TEST(GapLikelihood, MinusTwiceTheLogLikelihoodOfDrawsIsChiSquare) {
  // −2 log p(y) = n log 2π + log|S| + χ²_n for y from the model: mean
  // n log 2π + log|S| + n, variance 2n.
  std::mt19937_64 rng(11);
  const GaussianModel m = random_model(rng);
  const RunLikelihood lik(m);
  const int draws = 2000;
  const double n = static_cast<double>(lik.rows());
  double sum = 0.0;
  for (int k = 0; k < draws; ++k) sum += -2.0 * lik.log_likelihood(draw(m, rng));
  const double expected = n * std::log(2.0 * std::numbers::pi) + lik.log_det() + n;
  const double standard_error = std::sqrt(2.0 * n / draws);
  EXPECT_NEAR(sum / draws, expected, 4.0 * standard_error);
}

TEST(GapLikelihood, LogDetOfSIsTheDenseOne) {
  std::mt19937_64 rng(3);
  const GaussianModel m = random_model(rng);
  const Eigen::MatrixXd S =
      m.H * m.prior_var.asDiagonal() * m.H.transpose() + Eigen::MatrixXd(m.noise_var.asDiagonal());
  const Eigen::LLT<Eigen::MatrixXd> llt(S);
  const double dense = 2.0 * llt.matrixL().toDenseMatrix().diagonal().array().log().sum();
  EXPECT_NEAR(RunLikelihood(m).log_det(), dense, 1e-9 * std::abs(dense));
}

}  // namespace
}  // namespace insmc::runs
