// The covariance of the Allan variance estimates (N.3)–(N.4) against two
// things it does not compute itself: the equivalent degrees of freedom of
// NIST SP 1065 for white rate noise (a fit to simulations, within a few per
// cent), and the covariance of the estimates over simulated series. The
// longest levels take the trapezoid path (more than 4001 lags), the short
// ones the sum over whole lags.
#include "lib/noise/allan_covariance.h"

#include <cmath>
#include <gtest/gtest.h>

#include "lib/noise/noise_fit.h"
#include "tests/unit/lib/noise/synthetic_noise.h"

namespace insmc::noise {
namespace {

std::vector<AllanLevel> levels_of(const std::vector<double>& y, double dt) {
  const Segment all{0, y.size()};
  return overlapping_allan(y, dt, std::span(&all, 1));
}

TEST(AllanCovariance, WhiteRateMatchesTheDegreesOfFreedomOfNistSp1065) {
  const double dt = 0.01;
  const auto y = test::synthetic_series({.white = 1e-3}, 1 << 16, dt, 3);
  const std::vector<AllanLevel> levels = levels_of(y, dt);
  NoiseModel model;
  model[NoiseTerm::kWhiteRate] = 1e-6;
  const Eigen::MatrixXd cov = allan_covariance(levels, dt, model);
  ASSERT_GE(levels.back().cluster, 8192u);  // 4(a + b) lags and more: the trapezoid path
  for (std::size_t j = 0; j < levels.size(); ++j) {
    const double nu = model.avar(levels[j].tau_s);
    const double edf = 2 * nu * nu / cov(static_cast<Eigen::Index>(j), static_cast<Eigen::Index>(j));
    const double nist = allan_edf(levels[j], PowerLaw::kWhiteRate);
    // SP 1065's formula is an approximation to a few per cent (its Table 12);
    // where fewer than 3 degrees of freedom remain its clamp takes over.
    if (nist > 3) {
      EXPECT_NEAR(edf / nist, 1.0, 0.06) << "m = " << levels[j].cluster;
    }
  }
}

TEST(AllanCovariance, GaussMarkovAndWhiteMatchTheEstimatesOverSimulatedSeries) {
  // 8192 samples at 10 Hz, white 1e-3 unit·√s and a Gauss–Markov process of
  // 2e-3 unit with T_c = 5 s (its reach adds 500 lags: the 512-sample level
  // takes the trapezoid path). 400 series.
  const double dt = 0.1;
  const test::SyntheticNoise truth{.white = 1e-3, .gm_sigma = 2e-3, .gm_time_s = 5};
  NoiseModel model;
  model[NoiseTerm::kWhiteRate] = truth.white * truth.white;
  model[NoiseTerm::kGaussMarkov] = truth.gm_sigma * truth.gm_sigma;
  model.correlation_time_s = truth.gm_time_s;
  const int series = 400;
  std::vector<std::vector<double>> nu;  // [series][level]
  std::vector<AllanLevel> levels;
  for (int r = 0; r < series; ++r) {
    levels = levels_of(test::synthetic_series(truth, 8192, dt, 100 + static_cast<std::uint64_t>(r)), dt);
    std::vector<double> v;
    for (const AllanLevel& l : levels) v.push_back(l.avar);
    nu.push_back(v);
  }
  const Eigen::MatrixXd cov = allan_covariance(levels, dt, model);
  const auto J = levels.size();
  std::vector<double> mean(J, 0.0);
  for (const auto& v : nu)
    for (std::size_t j = 0; j < J; ++j) mean[j] += v[j] / series;
  auto sample_cov = [&](std::size_t p, std::size_t q) {
    double s = 0;
    for (const auto& v : nu) s += (v[p] - mean[p]) * (v[q] - mean[q]);
    return s / (series - 1);
  };
  bool trapezoid_level = false;
  for (std::size_t j = 2; j + 1 < J; ++j) {  // the levels with at least 4 windows' worth of data
    const auto ji = static_cast<Eigen::Index>(j);
    trapezoid_level = trapezoid_level || levels[j].cluster >= 512;
    // The sample variance of a scaled χ²(d) estimate has relative standard
    // deviation √((2 + 12/d)/R); 4.5 of them.
    const double edf = 2 * model.avar(levels[j].tau_s) * model.avar(levels[j].tau_s) / cov(ji, ji);
    const double rel_sd = std::sqrt((2 + 12 / edf) / series);
    EXPECT_NEAR(sample_cov(j, j) / cov(ji, ji), 1.0, 4.5 * rel_sd) << "m = " << levels[j].cluster;
    // Neighbouring levels' correlation: standard error (1 − ρ²)/√R.
    const double rho = cov(ji, ji + 1) / std::sqrt(cov(ji, ji) * cov(ji + 1, ji + 1));
    const double rho_hat = sample_cov(j, j + 1) / std::sqrt(sample_cov(j, j) * sample_cov(j + 1, j + 1));
    EXPECT_NEAR(rho_hat, rho, 4.5 * (1 - rho * rho) / std::sqrt(series)) << "m = " << levels[j].cluster;
  }
  EXPECT_TRUE(trapezoid_level);
}

}  // namespace
}  // namespace insmc::noise
