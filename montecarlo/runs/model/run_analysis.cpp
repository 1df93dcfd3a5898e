#include "montecarlo/runs/model/run_analysis.h"

#include <algorithm>
#include <Eigen/Eigenvalues>
#include <cmath>

#include "lib/common/assert.h"

namespace insmc::runs {

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
  // it well conditioned across causes of very different units: c = S u,
  // u ~ (0, I), P⁺ = S Π S with Π = (I + S Hᵀ R⁻¹ H S)⁻¹.
  const Eigen::VectorXd s = prior.cwiseSqrt();
  Eigen::MatrixXd info = (s.asDiagonal() * (H_.topRows(nt).transpose() * weighted_test_) * s.asDiagonal());
  info.diagonal().array() += 1.0;
  Eigen::MatrixXd pi;
  const Eigen::LLT<Eigen::MatrixXd> llt(info);
  if (llt.info() == Eigen::Success) {
    pi = llt.solve(Eigen::MatrixXd::Identity(d, d));
  } else {
    // Priors many orders wider than the data (a candidate's widened bounds)
    // leave round-off in the huge entries; info = I + (PSD) has every
    // eigenvalue ≥ 1, which the eigen-decomposition restores.
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(info);
    INSMC_ASSERT(eig.info() == Eigen::Success, "information matrix not decomposable ({} causes)", d);
    const Eigen::VectorXd inv = eig.eigenvalues().cwiseMax(1.0).cwiseInverse();
    pi = eig.eigenvectors() * inv.asDiagonal() * eig.eigenvectors().transpose();
  }
  posterior_ = s.asDiagonal() * pi * s.asDiagonal();
  // The actual test noise through the fit's gain, scaled: J = S Hₜᵀ R⁻¹ R_a R⁻¹ Hₜ S;
  // then A + B = S Π (I + J) Π S.
  const Eigen::ArrayXd actual_share = model.actual_noise_var.head(nt).array() / model.noise_var.head(nt).array();
  Eigen::MatrixXd spread = s.asDiagonal() *
                           (weighted_test_.transpose() * (H_.topRows(nt).array().colwise() * actual_share).matrix()) *
                           s.asDiagonal();
  spread.diagonal().array() += 1.0;
  const Eigen::MatrixXd around = pi * spread * pi;
  const Eigen::MatrixXd HS = H_ * s.asDiagonal();
  const Eigen::VectorXd q = ((HS * pi).array() * HS.array()).rowwise().sum();
  const Eigen::VectorXd ab = ((HS * around).array() * HS.array()).rowwise().sum();
  for (Eigen::Index a = 0; a < d; ++a) {
    const Eigen::Index j = active[static_cast<std::size_t>(a)];
    if (j < ux::kDim && 1.0 - pi(a, a) > kResolvedShare) {
      estimate_columns_.push_back(static_cast<int>(a));
      estimate_x_.push_back(static_cast<int>(j));
    }
  }
  const auto m = static_cast<Eigen::Index>(estimate_columns_.size());
  expected_.resize(n);
  actual_.resize(n + m);
  for (Eigen::Index i = 0; i < n; ++i) {
    const double r = model.noise_var[i], ra = model.actual_noise_var[i];
    expected_[i] = i < nt ? std::max(r - q[i], 1e-6 * r) : q[i] + r;
    actual_[i] = std::max(0.0, i < nt ? ab[i] + ra * (1.0 - 2.0 * q[i] / r) : ab[i] + ra);
  }
  estimate_var_.resize(m);
  for (Eigen::Index k = 0; k < m; ++k) {
    const int a = estimate_columns_[static_cast<std::size_t>(k)];
    // P − P⁺ and P − 2P⁺ + A + B, over the prior (scaled).
    estimate_var_[k] = prior[a] * (1.0 - pi(a, a));
    actual_[n + k] = std::max(0.0, (1.0 - 2.0 * pi(a, a) + around(a, a)) / (1.0 - pi(a, a)));
  }
  share_.resize(n + m);
  for (Eigen::Index i = 0; i < n + m; ++i) share_[i] = std::min(1.0, i < n ? actual_[i] / expected_[i] : actual_[i]);
}

GroupSums RunAnalyser::analyse(const Eigen::VectorXd& y) const {
  Eigen::VectorXd z;
  return analyse(y, z);
}

GroupSums RunAnalyser::analyse(const Eigen::VectorXd& data, Eigen::VectorXd& z) const {
  const Eigen::VectorXd v = normalized(data);
  z = v.head(data.size());
  return sums_of(v);
}

Eigen::VectorXd RunAnalyser::normalized(const Eigen::VectorXd& data) const {
  return normalized_linear(data - mean_.head(data.size()));
}

Eigen::VectorXd RunAnalyser::normalized_linear(const Eigen::VectorXd& y) const {
  // A run that stops early is the layout's first y.size() rows: the same
  // test rows, hence the same fit, and the navigation rows it has.
  const Eigen::Index n = y.size();
  INSMC_ASSERT(n >= test_rows_ && n <= H_.rows(), "run of {} values for a layout of {} rows ({} test rows)", n,
               H_.rows(), test_rows_);
  const auto m = static_cast<Eigen::Index>(estimate_columns_.size());
  const Eigen::VectorXd c = posterior_ * (weighted_test_.transpose() * y.head(test_rows_));
  Eigen::VectorXd v(n + m);
  v.head(n) = ((y - H_.topRows(n) * c).array() / expected_.head(n).array().sqrt()).matrix();
  for (Eigen::Index k = 0; k < m; ++k) v[n + k] = c[estimate_columns_[static_cast<std::size_t>(k)]] / std::sqrt(estimate_var_[k]);
  return v;
}

Eigen::MatrixXd RunAnalyser::estimate_map() const {
  const auto m = static_cast<Eigen::Index>(estimate_columns_.size());
  Eigen::MatrixXd W(m, test_rows_);
  for (Eigen::Index k = 0; k < m; ++k)
    W.row(k) = (weighted_test_ * posterior_.row(estimate_columns_[static_cast<std::size_t>(k)]).transpose()).transpose() /
               std::sqrt(estimate_var_[k]);
  return W;
}

GroupSums RunAnalyser::sums_of(const Eigen::VectorXd& v) const {
  GroupSums sums;
  const auto m = static_cast<Eigen::Index>(estimate_columns_.size());
  const Eigen::Index n = v.size() - m;  // the run's rows (a prefix of the layout's)
  const Eigen::Index all = static_cast<Eigen::Index>(layout_->rows.size());
  for (Eigen::Index i = 0; i < v.size(); ++i) {
    const Eigen::Index term = i < n ? i : all + (i - n);  // index into the layout's terms
    const int g = i < n ? layout_->rows[static_cast<std::size_t>(i)].group : kEstimatesGroup;
    sums.z2[g] += v[i] * v[i];
    sums.count[g] += 1.0;
    sums.expected[g] += share_[term];
    sums.floor[g] += 1.0 - share_[term];
  }
  return sums;
}

}  // namespace insmc::runs
