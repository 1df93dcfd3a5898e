// The band of a unit's test-row chi-square (compensate/unit_prediction.h):
// its trace formulas against the chi-square of rows drawn from the model
// (y = H c + e, c of the prior variances, e of the actual noise), as a
// sample mean and variance over many draws, not against themselves.
#include <gtest/gtest.h>

#include <Eigen/Cholesky>
#include <boost/math/distributions/normal.hpp>
#include <cmath>
#include <random>
#include <vector>

#include "montecarlo/records/compensate/unit_prediction.h"

namespace insmc::compensate {
namespace {

constexpr int kRows = 40, kCauses = 12, kDraws = 20000;

/// A model whose floor (noise_var − actual_noise_var) is half of some rows'
/// noise and none of others', like the r rows' floor against the f rows.
runs::GaussianModel model_with_floor() {
  std::mt19937_64 gen(7);
  std::normal_distribution<double> n01;
  runs::GaussianModel m;
  m.mean = Eigen::VectorXd::Zero(kRows);
  m.H = Eigen::MatrixXd::NullaryExpr(kRows, kCauses, [&] { return n01(gen); });
  m.prior_var = Eigen::VectorXd::LinSpaced(kCauses, 0.5, 3.0);
  m.actual_noise_var = Eigen::VectorXd::LinSpaced(kRows, 0.2, 2.0);
  m.noise_var = m.actual_noise_var;
  for (int i = 0; i < kRows; i += 2) m.noise_var[i] += 4.0;
  return m;
}

/// S = H P Hᵀ + W, W the noise with the floor.
Eigen::LLT<Eigen::MatrixXd> row_covariance(const runs::GaussianModel& m) {
  Eigen::MatrixXd S = m.H * m.prior_var.asDiagonal() * m.H.transpose();
  S.diagonal() += m.noise_var;
  return Eigen::LLT<Eigen::MatrixXd>(S);
}

/// The chi-squares of kDraws rows drawn from the model; `uniform`: the
/// causes uniform (Table 3.1's draws) instead of Gaussian.
std::vector<double> drawn_chi2s(const runs::GaussianModel& m, const Eigen::LLT<Eigen::MatrixXd>& S, bool uniform,
                                std::uint64_t seed) {
  std::mt19937_64 gen(seed);
  std::normal_distribution<double> n01;
  std::uniform_real_distribution<double> u11(-1.0, 1.0);
  std::vector<double> q;
  for (int d = 0; d < kDraws; ++d) {
    Eigen::VectorXd c(kCauses), e(kRows);
    for (int j = 0; j < kCauses; ++j)
      c[j] = std::sqrt(m.prior_var[j]) * (uniform ? std::sqrt(3.0) * u11(gen) : n01(gen));
    for (int i = 0; i < kRows; ++i) e[i] = std::sqrt(m.actual_noise_var[i]) * n01(gen);
    const Eigen::VectorXd y = m.H * c + e;
    q.push_back(y.dot(S.solve(y)));
  }
  return q;
}

struct Moments {
  double mean, variance, se_mean, se_variance;
};

Moments moments(const std::vector<double>& q) {
  double s1 = 0, s2 = 0, s3 = 0, s4 = 0;
  for (const double v : q) s1 += v, s2 += v * v, s3 += v * v * v, s4 += v * v * v * v;
  const double n = static_cast<double>(q.size()), mean = s1 / n, m2 = s2 / n - mean * mean;
  const double m4 = s4 / n - 4 * mean * s3 / n + 6 * mean * mean * s2 / n - 3 * std::pow(mean, 4);
  return {mean, m2, std::sqrt(m2 / n), std::sqrt(std::max(m4 - m2 * m2, 0.0) / n)};
}

TEST(ConsistencyBand, ItsMeanAndSpreadAreThoseOfRowsDrawnFromTheModel) {
  const runs::GaussianModel m = model_with_floor();
  const Eigen::LLT<Eigen::MatrixXd> llt = row_covariance(m);
  const ConsistencyBand band = consistency_band(m, llt);
  // The floor takes something off: below the rows' count, above nothing.
  EXPECT_LT(band.linear_mean, kRows);
  EXPECT_GT(band.linear_mean, 0.5 * kRows);
  // Four standard errors each side: about 6e-5 two-sided per check.
  const Moments g = moments(drawn_chi2s(m, llt, false, 20261206));
  EXPECT_NEAR(g.mean, band.linear_mean, 4 * g.se_mean);
  EXPECT_NEAR(g.variance, band.linear_sd * band.linear_sd, 4 * g.se_variance);
  // Uniform causes: the same mean, a spread no wider (less kurtosis).
  const Moments u = moments(drawn_chi2s(m, llt, true, 20261206));
  EXPECT_NEAR(u.mean, band.linear_mean, 4 * u.se_mean);
  EXPECT_LE(u.variance, band.linear_sd * band.linear_sd + 4 * u.se_variance);
}

TEST(ConsistencyBand, ItsTailProbabilityIsThatOfRowsDrawnFromTheModel) {
  // Satterthwaite's c·χ²(ν) against the drawn chi-squares' own tail: the
  // share of draws beyond the band's 1 % point is binomial(kDraws, 0.01) if
  // the approximation holds there (4 of its sigmas).
  const runs::GaussianModel m = model_with_floor();
  const Eigen::LLT<Eigen::MatrixXd> llt = row_covariance(m);
  const ConsistencyBand band = consistency_band(m, llt);
  double lo = band.linear_mean, hi = band.linear_mean + 20 * band.linear_sd;
  for (int i = 0; i < 200; ++i) (band.linear_p(0.5 * (lo + hi)) > 0.01 ? lo : hi) = 0.5 * (lo + hi);
  int beyond = 0;
  for (const double q : drawn_chi2s(m, llt, false, 99)) beyond += q > lo;
  const double expected = 0.01 * kDraws;
  EXPECT_NEAR(beyond, expected, 4 * std::sqrt(expected * 0.99));
  EXPECT_DOUBLE_EQ(ConsistencyBand{}.linear_p(5.0), 1.0);
}

TEST(ConsistencyBand, WithoutAFloorItIsTheChiSquareOfTheRows) {
  runs::GaussianModel m = model_with_floor();
  m.noise_var = m.actual_noise_var;
  const ConsistencyBand band = consistency_band(m, row_covariance(m));
  EXPECT_NEAR(band.linear_mean, kRows, 1e-9 * kRows);
  EXPECT_NEAR(band.linear_sd, std::sqrt(2.0 * kRows), 1e-9 * kRows);
}

}  // namespace
}  // namespace insmc::compensate
