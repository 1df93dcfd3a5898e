#include "montecarlo/records/runs/model/likelihood.h"

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

namespace {

/// H s of the causes of nonzero prior.
Eigen::MatrixXd scaled_active(const GaussianModel& model) {
  std::vector<Eigen::Index> active;
  for (Eigen::Index j = 0; j < model.prior_var.size(); ++j)
    if (model.prior_var[j] > 0) active.push_back(j);
  Eigen::MatrixXd W(model.H.rows(), static_cast<Eigen::Index>(active.size()));
  for (std::size_t a = 0; a < active.size(); ++a)
    W.col(static_cast<Eigen::Index>(a)) = model.H.col(active[a]) * std::sqrt(model.prior_var[active[a]]);
  return W;
}

/// As in run_analysis.cpp: a downdate keeps every eigenvalue of I − Gᵀ M⁻¹ G
/// above this, and k below this share of the causes.
constexpr double kLeastKept = 1e-3;
constexpr double kDowndateShare = 0.5;

}  // namespace

LatticeLikelihood::LatticeLikelihood(const GaussianModel& model) : model_(model), mean_(model.mean) {
  const Eigen::Index n = model.H.rows();
  if (mean_.size() != n) mean_ = Eigen::VectorXd::Zero(n);
  INSMC_ASSERT((model.noise_var.array() > 0.0).all(), "noise variance must be positive on every row");
  inv_noise_ = model.noise_var.cwiseInverse();
  W_ = scaled_active(model);
  Eigen::MatrixXd M = W_.transpose() * inv_noise_.asDiagonal() * W_;
  M.diagonal().array() += 1.0;
  llt_.compute(M);
  factorized_ = llt_.info() == Eigen::Success;
  if (factorized_) log_det_m_ = 2.0 * llt_.matrixLLT().diagonal().array().log().sum();
}

RunLikelihood::RunLikelihood(const LatticeLikelihood& lattice, std::span<const Eigen::Index> rows) {
  const auto n = static_cast<Eigen::Index>(rows.size());
  const Eigen::Index d = lattice.W_.cols();
  // The rows the layout lacks.
  std::vector<Eigen::Index> missing;
  for (Eigen::Index m = 0, i = 0; m < lattice.W_.rows(); ++m) {
    if (i < n && rows[static_cast<std::size_t>(i)] == m) ++i;
    else missing.push_back(m);
  }
  const auto k = static_cast<Eigen::Index>(missing.size());
  const auto fit_anew = [&] { *this = RunLikelihood(select_rows(lattice.model_, rows)); };
  // k = 0: the lattice itself (a file whose runs share one layout), fitted as
  // any layout of its own is.
  if (k == 0 || !lattice.factorized_ || static_cast<double>(k) > kDowndateShare * static_cast<double>(d)) {
    fit_anew();
    return;
  }
  Eigen::MatrixXd G(d, k);
  for (Eigen::Index j = 0; j < k; ++j) {
    const Eigen::Index m = missing[static_cast<std::size_t>(j)];
    G.col(j) = lattice.W_.row(m).transpose() * std::sqrt(lattice.inv_noise_[m]);
  }
  Eigen::MatrixXd U = lattice.llt_.solve(G);
  Eigen::MatrixXd kept = -G.transpose() * U;
  kept.diagonal().array() += 1.0;
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(kept);
  if (eig.info() != Eigen::Success || !(eig.eigenvalues().minCoeff() > kLeastKept)) {
    fit_anew();
    return;
  }
  lattice_ = &lattice;
  mean_.resize(n);
  inv_noise_.resize(n);
  weighted_.resize(n, d);
  for (Eigen::Index i = 0; i < n; ++i) {
    const Eigen::Index m = rows[static_cast<std::size_t>(i)];
    mean_[i] = lattice.mean_[m];
    inv_noise_[i] = lattice.inv_noise_[m];
    weighted_.row(i) = lattice.W_.row(m) * lattice.inv_noise_[m];
  }
  C_ = eig.eigenvectors() * eig.eigenvalues().cwiseInverse().asDiagonal() * eig.eigenvectors().transpose();
  U_ = std::move(U);
  log_det_ = -inv_noise_.array().log().sum() + lattice.log_det_m_ + eig.eigenvalues().array().log().sum();
}

double RunLikelihood::log_likelihood(const Eigen::VectorXd& y) const {
  INSMC_ASSERT(y.size() == mean_.size(), "run has {} values, model {} rows", y.size(), mean_.size());
  const Eigen::VectorXd r = y - mean_;
  double reduced = 0.0;  // bᵀ M⁻¹ b
  if (lattice_) {
    const Eigen::VectorXd b = weighted_.transpose() * r;
    const Eigen::VectorXd u = U_.transpose() * b;
    reduced = b.dot(lattice_->llt_.solve(b)) + u.dot(C_ * u);
  } else {
    reduced = (whiten_ * r).squaredNorm();
  }
  const double quadratic = r.dot(inv_noise_.cwiseProduct(r)) - reduced;
  const double n = static_cast<double>(mean_.size());
  return -0.5 * (n * std::log(2.0 * std::numbers::pi) + log_det_ + quadratic);
}

}  // namespace insmc::runs
