#include "lib/preflight/estimate_uncertainty.h"

#include "lib/common/assert.h"
#include "lib/preflight/observables.h"
#include "lib/propagation/linear_model.h"
#include "lib/propagation/paper_model.h"

namespace insmc {

EstimateErrors estimate_errors(System system, Fidelity fidelity, const ModelOptions& m, const TestRunOptions& test,
                               const TestRunEstimators& est, const UncertaintyModel& uncertainties) {
  INSMC_ASSERT(fidelity != Fidelity::kTruth, "estimate errors exist for the linear-in-x levels only");
  const int K = test.intervals();
  const double tau = test.filter_interval_s, T = test.duration_s;
  const TestRunMaps maps = test_run_maps(system, fidelity, m, test);
  const ShortRunMatrices paper = paper_short_run_matrices(system, m);
  const Sensitivity3 df_at_end = fidelity == Fidelity::kPaper ? paper_accelerometer_error(paper, T, m)
                                                               : LinearErrorModel(system, m).forcing(T);
  // Quantization: Δr_k carries e_k − e_0, Δf_k carries (U_{k−1} − U_k)/τ.
  const double q = test.position_resolution_m, w = test.dv_pulse_mps;
  Eigen::MatrixXd position_noise = q * q / 12 * (Eigen::MatrixXd::Identity(K, K) + Eigen::MatrixXd::Ones(K, K));
  Eigen::MatrixXd accel_noise = Eigen::MatrixXd::Zero(K, K);
  for (int k = 0; k < K; ++k) {
    accel_noise(k, k) = 2 * w * w / 12 / (tau * tau);
    if (k + 1 < K) accel_noise(k, k + 1) = accel_noise(k + 1, k) = -w * w / 12 / (tau * tau);
  }
  // The first interval's U_0 is the counter's remainder at switch-over, as
  // random as the others.
  const UncertaintyVector mu = uncertainties.mean(), var = uncertainties.variance();
  EstimateErrors out;
  for (int a = 0; a < 3; ++a) {
    Eigen::MatrixXd position_rows(K, ux::kDim), accel_rows(K, ux::kDim);
    for (int k = 1; k <= K; ++k) {
      position_rows.row(k - 1) = maps.position_change[k].row(a);
      accel_rows.row(k - 1) = (maps.velocity_increment[k].row(a) - maps.velocity_increment[k - 1].row(a)) / tau;
    }
    Eigen::Matrix<double, kEstimateRows, ux::kDim> e = apply_estimators<ux::kDim>(est, m, T, position_rows, accel_rows);
    e.row(kU2Row) -= paper.u2.row(a);
    e.row(kU3Row) -= paper.u3.row(a);
    e.row(kU3AccelRow) -= paper.u3.row(a);
    e.row(kDfAtTestEndRow) -= df_at_end.row(a);
    out.x_map[a] = e;
    // The estimators applied to unit data: the noise's weights.
    const Eigen::MatrixXd unit = Eigen::MatrixXd::Identity(K, K);
    const Eigen::MatrixXd from_position = apply_estimators(est, m, T, unit, Eigen::MatrixXd::Zero(K, K));
    const Eigen::MatrixXd from_accel = apply_estimators(est, m, T, Eigen::MatrixXd::Zero(K, K), unit);
    out.noise_covariance[a] = from_position * position_noise * from_position.transpose() +
                              from_accel * accel_noise * from_accel.transpose();
    out.mean[a] = e * mu;
    out.covariance[a] = e * var.asDiagonal() * e.transpose() + out.noise_covariance[a];
  }
  return out;
}

}  // namespace insmc
