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
  e.mean = unit * w.mean;  // after a realignment the response restarts the input: the same mean again
  const runs::Layout& layout = *ctx.layout;
  const Eigen::Index n = unit.rows(), nt = layout.test_rows;
  if (layout.nav == runs::NavSegment::kRestart && nt < n) {
    // A realignment draws the misalignment anew (its first order has a
    // column of its own, scheme_rows.h): the spread after it is independent
    // of the test run's, columns of its own.
    e.columns = Eigen::MatrixXd::Zero(n, 12);
    e.columns.topLeftCorner(nt, 6) = unit.topRows(nt);
    e.columns.bottomRightCorner(n - nt, 6) = unit.bottomRows(n - nt);
    e.column_var.resize(12);
    e.column_var << w.variance, w.variance;
    return;
  }
  e.columns = unit;
  e.column_var = w.variance;
}

}  // namespace insmc::gap::candidates
