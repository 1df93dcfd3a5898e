#include "montecarlo/records/gap/candidates/misalignment_second_order.h"

#include "montecarlo/records/gap/candidates/common.h"

namespace insmc::gap::candidates {

Eigen::Matrix<double, 3, 6> second_order_unit_terms(const Eigen::Vector3d& f) {
  Eigen::Matrix<double, 3, 6> B = Eigen::Matrix<double, 3, 6>::Zero();
  for (int c = 0; c < 6; ++c) {
    const int i = kSecondOrderTerms[static_cast<std::size_t>(c)][0];
    const int j = kSecondOrderTerms[static_cast<std::size_t>(c)][1];
    B(i, c) += 0.5 * f[j];
    B(j, c) += 0.5 * f[i];
    if (i == j) B.col(c) = 0.5 * (B.col(c) - f);
  }
  return B;
}

SecondOrderWeights second_order_weights(const Eigen::Vector3d& sigma_rad) {
  SecondOrderWeights w;
  for (int c = 0; c < 6; ++c) {
    const int i = kSecondOrderTerms[static_cast<std::size_t>(c)][0];
    const int j = kSecondOrderTerms[static_cast<std::size_t>(c)][1];
    const double product = sigma_rad[i] * sigma_rad[j];
    w.mean[c] = i == j ? product : 0.0;
    w.variance[c] = (i == j ? 2.0 : 1.0) * product * product;
  }
  return w;
}

void add_misalignment_second_order(const LayoutContext& ctx, const Eigen::Vector3d& sigma_rad, runs::Extension& e) {
  const ModelOptions m = ctx.site->model;
  const Eigen::MatrixXd unit =
      signature_columns(ctx, "misalignment_second_order", 6, [m](double t, runs::Columns3& a, runs::Columns3& th) {
        th.setZero();
        a = second_order_unit_terms(specific_force(t, m));
      });
  const SecondOrderWeights w = second_order_weights(sigma_rad);
  e.columns_higher_order = true;  // the test run's estimates see the first order (ζ_r) alone
  e.mean = unit * w.mean;
  e.columns = unit;
  e.column_var = w.variance;
}

}  // namespace insmc::gap::candidates
