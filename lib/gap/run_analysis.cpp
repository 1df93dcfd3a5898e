#include "lib/gap/run_analysis.h"

#include <algorithm>
#include <Eigen/Eigenvalues>
#include <cmath>

#include "lib/common/assert.h"

namespace insmc::gap {

RunAnalyser::RunAnalyser(const Layout& layout, const GaussianModel& model)
    : layout_(&layout), mean_(model.mean), test_rows_(layout.test_rows) {
  const Eigen::Index n = model.H.rows();
  if (mean_.size() != n) mean_ = Eigen::VectorXd::Zero(n);
  INSMC_ASSERT(n == static_cast<Eigen::Index>(layout.rows.size()), "rows {} vs layout {}", n, layout.rows.size());
  // Causes with zero prior variance are known exactly: drop them.
  std::vector<Eigen::Index> active;
  for (Eigen::Index j = 0; j < model.prior_var.size(); ++j)
    if (model.prior_var[j] > 0) active.push_back(j);
  const auto d = static_cast<Eigen::Index>(active.size());
  H_.resize(n, d);
  Eigen::VectorXd prior(d);
  for (Eigen::Index a = 0; a < d; ++a) {
    H_.col(a) = model.H.col(active[static_cast<std::size_t>(a)]);
    prior[a] = model.prior_var[active[static_cast<std::size_t>(a)]];
  }
  const Eigen::Index nt = test_rows_;
  weighted_test_ = H_.topRows(nt).array().colwise() / model.noise_var.head(nt).array();
  // Information form: (P⁻¹ + Hᵀ R⁻¹ H)⁻¹ = P⁺. Scaling by the prior std keeps
  // it well conditioned across causes of very different units.
  const Eigen::VectorXd s = prior.cwiseSqrt();
  Eigen::MatrixXd info = (s.asDiagonal() * (H_.topRows(nt).transpose() * weighted_test_) * s.asDiagonal());
  info.diagonal().array() += 1.0;
  const Eigen::LLT<Eigen::MatrixXd> llt(info);
  if (llt.info() == Eigen::Success) {
    posterior_ = s.asDiagonal() * llt.solve(Eigen::MatrixXd::Identity(d, d)) * s.asDiagonal();
  } else {
    // Priors many orders wider than the data (a candidate's widened bounds)
    // leave round-off in the huge entries; info = I + (PSD) has every
    // eigenvalue ≥ 1, which the eigen-decomposition restores.
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(info);
    INSMC_ASSERT(eig.info() == Eigen::Success, "information matrix not decomposable ({} causes)", d);
    const Eigen::VectorXd inv = eig.eigenvalues().cwiseMax(1.0).cwiseInverse();
    posterior_ = s.asDiagonal() * (eig.eigenvectors() * inv.asDiagonal() * eig.eigenvectors().transpose()) *
                 s.asDiagonal();
  }
  const Eigen::VectorXd q = ((H_ * posterior_).array() * H_.array()).rowwise().sum();
  expected_.resize(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const double r = model.noise_var[i];
    expected_[i] = i < nt ? std::max(r - q[i], 1e-6 * r) : q[i] + r;
  }
  for (Eigen::Index a = 0; a < d; ++a) {
    const Eigen::Index j = active[static_cast<std::size_t>(a)];
    const double reduced = prior[a] - posterior_(a, a);
    if (j < ux::kDim && reduced > kResolvedShare * prior[a]) estimate_columns_.push_back(static_cast<int>(a));
  }
  estimate_var_.resize(static_cast<Eigen::Index>(estimate_columns_.size()));
  for (std::size_t k = 0; k < estimate_columns_.size(); ++k) {
    const int a = estimate_columns_[k];
    estimate_var_[static_cast<Eigen::Index>(k)] = prior[a] - posterior_(a, a);
  }
}

GroupSums RunAnalyser::analyse(const Eigen::VectorXd& y) const {
  Eigen::VectorXd z;
  return analyse(y, z);
}

GroupSums RunAnalyser::analyse(const Eigen::VectorXd& data, Eigen::VectorXd& z) const {
  const Eigen::VectorXd v = normalized(data);
  z = v.head(static_cast<Eigen::Index>(layout_->rows.size()));
  return sums_of(v);
}

Eigen::VectorXd RunAnalyser::normalized_linear(const Eigen::VectorXd& y) const {
  const auto n = static_cast<Eigen::Index>(layout_->rows.size());
  const auto m = static_cast<Eigen::Index>(estimate_columns_.size());
  const Eigen::VectorXd c = posterior_ * (weighted_test_.transpose() * y.head(test_rows_));
  Eigen::VectorXd v(n + m);
  v.head(n) = ((y - H_ * c).array() / expected_.array().sqrt()).matrix();
  for (Eigen::Index k = 0; k < m; ++k) v[n + k] = c[estimate_columns_[static_cast<std::size_t>(k)]] / std::sqrt(estimate_var_[k]);
  return v;
}

GroupSums RunAnalyser::sums_of(const Eigen::VectorXd& v) const {
  GroupSums sums;
  const auto n = static_cast<Eigen::Index>(layout_->rows.size());
  for (Eigen::Index i = 0; i < n; ++i) {
    const int g = layout_->rows[static_cast<std::size_t>(i)].group;
    sums.z2[g] += v[i] * v[i];
    sums.count[g] += 1.0;
  }
  for (Eigen::Index k = n; k < v.size(); ++k) {
    sums.z2[kEstimatesGroup] += v[k] * v[k];
    sums.count[kEstimatesGroup] += 1.0;
  }
  return sums;
}

}  // namespace insmc::gap
