#include "montecarlo/runs/model/likelihood.h"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <cmath>
#include <numbers>
#include <vector>

#include "lib/common/assert.h"

namespace insmc::runs {

RunLikelihood::RunLikelihood(const GaussianModel& model) : mean_(model.mean) {
  const Eigen::Index n = model.H.rows();
  if (mean_.size() != n) mean_ = Eigen::VectorXd::Zero(n);
  INSMC_ASSERT(model.noise_var.size() == n, "noise rows {} vs H rows {}", model.noise_var.size(), n);
  INSMC_ASSERT((model.noise_var.array() > 0.0).all(), "noise variance must be positive on every row");
  inv_noise_ = model.noise_var.cwiseInverse();
  // Causes with zero prior variance are known exactly: drop them. The rest
  // scaled by their prior std: W = H s.
  std::vector<Eigen::Index> active;
  for (Eigen::Index j = 0; j < model.prior_var.size(); ++j)
    if (model.prior_var[j] > 0) active.push_back(j);
  const auto d = static_cast<Eigen::Index>(active.size());
  Eigen::MatrixXd W(n, d);
  for (Eigen::Index a = 0; a < d; ++a) {
    const Eigen::Index j = active[static_cast<std::size_t>(a)];
    W.col(a) = model.H.col(j) * std::sqrt(model.prior_var[j]);
  }
  const Eigen::MatrixXd G = W.transpose() * inv_noise_.asDiagonal();  // b = G r
  Eigen::MatrixXd M = G * W;
  M.diagonal().array() += 1.0;
  double log_det_m = 0.0;
  const Eigen::LLT<Eigen::MatrixXd> llt(M);
  if (llt.info() == Eigen::Success) {
    log_det_m = 2.0 * llt.matrixL().toDenseMatrix().diagonal().array().log().sum();
    whiten_ = llt.matrixL().solve(G);
  } else {
    // Priors many orders wider than the data leave round-off in the huge
    // entries; M = I + (PSD) has every eigenvalue ≥ 1, which the
    // eigen-decomposition restores (as run_analysis.cpp does).
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(M);
    INSMC_ASSERT(eig.info() == Eigen::Success, "information matrix not decomposable ({} causes)", d);
    const Eigen::VectorXd lambda = eig.eigenvalues().cwiseMax(1.0);
    log_det_m = lambda.array().log().sum();
    whiten_ = lambda.cwiseSqrt().cwiseInverse().asDiagonal() * (eig.eigenvectors().transpose() * G);
  }
  log_det_ = -inv_noise_.array().log().sum() + log_det_m;
}

double RunLikelihood::log_likelihood(const Eigen::VectorXd& y) const {
  INSMC_ASSERT(y.size() == mean_.size(), "run has {} values, model {} rows", y.size(), mean_.size());
  const Eigen::VectorXd r = y - mean_;
  const double quadratic = r.dot(inv_noise_.cwiseProduct(r)) - (whiten_ * r).squaredNorm();
  const double n = static_cast<double>(mean_.size());
  return -0.5 * (n * std::log(2.0 * std::numbers::pi) + log_det_ + quadratic);
}

}  // namespace insmc::runs
