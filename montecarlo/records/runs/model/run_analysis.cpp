#include "montecarlo/records/runs/model/run_analysis.h"

#include <algorithm>
#include <Eigen/Eigenvalues>
#include <cmath>
#include <functional>
#include <mutex>
#include <numeric>

#include "lib/common/assert.h"
#include "montecarlo/records/runs/model/quadratic_forms.h"
#include "montecarlo/records/runs/model/row_column_groups.h"
#include "montecarlo/records/runs/model/row_subset.h"

namespace insmc::runs {

namespace {

/// (I + PSD)⁻¹ of an information matrix in scaled causes.
Eigen::MatrixXd inverse_of_information(const Eigen::MatrixXd& info) {
  const Eigen::Index d = info.rows();
  const Eigen::LLT<Eigen::MatrixXd> llt(info);
  if (llt.info() == Eigen::Success) return llt.solve(Eigen::MatrixXd::Identity(d, d));
  // Priors many orders wider than the data (a candidate's widened bounds)
  // leave round-off in the huge entries; info = I + (PSD) has every
  // eigenvalue ≥ 1, which the eigen-decomposition restores.
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(info);
  INSMC_ASSERT(eig.info() == Eigen::Success, "information matrix not decomposable ({} causes)", d);
  const Eigen::VectorXd inv = eig.eigenvalues().cwiseMax(1.0).cwiseInverse();
  return eig.eigenvectors() * inv.asDiagonal() * eig.eigenvectors().transpose();
}

/// A Woodbury downdate of k test rows is worth it while k is below this
/// share of the causes the test rows see, p (O(n p k) against the O(n p²)
/// of the rows' terms from a posterior of the layout's own), and is exact to round-off while
/// the information left, I − Gᵀ Π G, keeps every eigenvalue above
/// kLeastKeptInformation. Beyond that share the layout's information is the
/// lattice's less the rows it lacks, while each cause keeps more than
/// kLeastKeptInformation of its own.
constexpr double kDowndateShare = 0.25;

/// How many leading columns of A the first `test_rows` rows touch: one past
/// the last column with a nonzero there. The causes beyond it (a random
/// process' knots after the test run) are not seen by the fit and keep
/// their prior.
Eigen::Index observed_columns(const Eigen::MatrixXd& a, Eigen::Index test_rows) {
  for (Eigen::Index c = a.cols(); c > 0; --c)
    if ((a.col(c - 1).head(test_rows).array() != 0.0).any()) return c;
  return 0;
}

/// Each row's h M hᵀ for a matrix M over the first M.rows() columns and the
/// identity beyond them (the scaled posterior of causes the fit does not
/// see), `unseen` each row's |h|² over those; each group of rows over the
/// columns it sees (`blocks`, row_column_groups.h).
Eigen::VectorXd row_forms(const std::vector<Eigen::MatrixXd>& blocks, const Eigen::MatrixXd& m,
                          const Eigen::VectorXd& unseen, const RowColumnGroups& groups) {
  if (unseen.size() == 0 || m.rows() == 0) return unseen;
  return grouped_row_quadratic_forms(blocks, m, groups, unseen.size()) + unseen;
}

}  // namespace

LatticeAnalysis::LatticeAnalysis(const Layout& lattice, const GaussianModel& model)
    : layout_(&lattice), mean_(model.mean), test_rows_(lattice.test_rows) {
  const Eigen::Index n = model.H.rows();
  if (mean_.size() != n) mean_ = Eigen::VectorXd::Zero(n);
  INSMC_ASSERT(n == static_cast<Eigen::Index>(lattice.rows.size()), "rows {} vs layout {}", n, lattice.rows.size());
  // Causes with zero prior variance are known exactly: drop them.
  for (Eigen::Index j = 0; j < model.prior_var.size(); ++j)
    if (model.prior_var[j] > 0) active_.push_back(j);
  const auto d = static_cast<Eigen::Index>(active_.size());
  Eigen::MatrixXd H(n, d);
  prior_.resize(d);
  for (Eigen::Index a = 0; a < d; ++a) {
    H.col(a) = model.H.col(active_[static_cast<std::size_t>(a)]);
    prior_[a] = model.prior_var[active_[static_cast<std::size_t>(a)]];
  }
  H_ = std::make_shared<const Eigen::MatrixXd>(std::move(H));
  noise_var_ = model.noise_var;
  actual_noise_var_ = model.actual_noise_var;
  fit(true);
}

LatticeAnalysis::LatticeAnalysis(const Layout& layout, const LatticeAnalysis& lattice, std::span<const Eigen::Index> rows)
    : layout_(&layout),
      mean_(rows_of(lattice.mean_, rows)),
      H_(std::make_shared<const Eigen::MatrixXd>(rows_of(*lattice.H_, rows))),
      prior_(lattice.prior_),
      s_(lattice.s_),
      active_(lattice.active_),
      noise_var_(rows_of(lattice.noise_var_, rows)),
      actual_noise_var_(rows_of(lattice.actual_noise_var_, rows)),
      test_rows_(layout.test_rows),
      observed_(lattice.observed_) {}

LatticeAnalysis::LatticeAnalysis(const LatticeAnalysis& lattice, std::span<const Eigen::Index> rows,
                                 const Eigen::MatrixXd& G, const Eigen::VectorXd& share)
    : layout_(lattice.layout_), s_(lattice.s_), observed_(lattice.observed_) {
  // The information and the spread are sums over the test rows: the
  // lattice's less the rows the layout lacks.
  // Symmetric: the lower triangles are formed (half the products'
  // work), then mirrored.
  Eigen::MatrixXd info = lattice.info_, spread = lattice.spread_;
  info.triangularView<Eigen::Lower>() -= G * G.transpose();
  spread.triangularView<Eigen::Lower>() -= G * share.asDiagonal() * G.transpose();
  info.triangularView<Eigen::StrictlyUpper>() = info.transpose();
  spread.triangularView<Eigen::StrictlyUpper>() = spread.transpose();
  // Each group of rows over the causes it sees, gathered from the
  // lattice's H and scaled in one pass, not cut and then scaled; each row's
  // terms over the causes the fit does not see are the lattice's.
  const Eigen::VectorXd unseen = rows_of(lattice.unseen_, rows);
  const RowColumnGroups groups = lattice.groups_of(rows);
  const std::vector<Eigen::MatrixXd> blocks = group_blocks(*lattice.H_, groups, rows, s_);
  solve(std::move(info), std::move(spread));
  ab_ = row_forms(blocks, around_, unseen, groups);
  q_ = row_forms(blocks, pi_, unseen, groups);
}

RowColumnGroups LatticeAnalysis::groups_of(std::span<const Eigen::Index> rows) const {
  RowColumnGroups g;
  g.columns = groups_.columns;
  g.rows.resize(groups_.columns.size());
  for (std::size_t i = 0; i < rows.size(); ++i)
    g.rows[static_cast<std::size_t>(group_of_row_[static_cast<std::size_t>(rows[i])])].push_back(
        static_cast<Eigen::Index>(i));
  return g;
}

void LatticeAnalysis::fit(bool lattice) {
  const Eigen::Index nt = test_rows_;
  // Information form: (P⁻¹ + Hᵀ R⁻¹ H)⁻¹ = P⁺. Scaling by the prior std keeps
  // it well conditioned across causes of very different units: c = S u,
  // u ~ (0, I), P⁺ = S Π S with Π = (I + S Hᵀ R⁻¹ H S)⁻¹.
  s_ = prior_.cwiseSqrt();
  const Eigen::MatrixXd HS = *H_ * s_.asDiagonal();
  // The information is zero beyond the causes the test rows touch: the
  // fit's matrices are those columns' (Π is the identity beyond them).
  observed_ = observed_columns(HS, nt);
  const Eigen::VectorXd inverse_noise = noise_var_.head(nt).cwiseInverse();
  Eigen::MatrixXd info = weighted_gram(HS.topLeftCorner(nt, observed_), inverse_noise);
  info.diagonal().array() += 1.0;
  // The actual test noise through the fit's gain, scaled: J = S Hₜᵀ R⁻¹ R_a R⁻¹ Hₜ S;
  // then A + B = S Π (I + J) Π S.
  const Eigen::VectorXd actual_weight = actual_noise_var_.head(nt).cwiseProduct(inverse_noise.cwiseAbs2());
  Eigen::MatrixXd spread = weighted_gram(HS.topLeftCorner(nt, observed_), actual_weight);
  spread.diagonal().array() += 1.0;
  RowColumnGroups groups = group_rows_by_columns(HS, observed_);
  solve(std::move(info), std::move(spread));
  unseen_ = HS.rightCols(HS.cols() - observed_).rowwise().squaredNorm();
  if (lattice) {
    // Its layouts take their rows' groups from its own; its rows' terms are
    // made when a layout first asks (row_terms).
    group_of_row_.resize(static_cast<std::size_t>(HS.rows()));
    for (std::size_t g = 0; g < groups.rows.size(); ++g)
      for (Eigen::Index i : groups.rows[g]) group_of_row_[static_cast<std::size_t>(i)] = static_cast<int>(g);
    groups_.columns = std::move(groups.columns);
    return;
  }
  const std::vector<Eigen::MatrixXd> blocks = group_blocks(HS, groups, {}, {});
  ab_ = row_forms(blocks, around_, unseen_, groups);
  q_ = row_forms(blocks, pi_, unseen_, groups);
}

const LatticeAnalysis::RowTerms& LatticeAnalysis::row_terms() const {
  std::call_once(row_terms_once_, [this] {
    const Eigen::MatrixXd HS = *H_ * s_.asDiagonal();
    std::vector<Eigen::Index> all(static_cast<std::size_t>(HS.rows()));
    std::iota(all.begin(), all.end(), Eigen::Index{0});
    const RowColumnGroups groups = groups_of(all);
    row_terms_.ab = row_forms(group_blocks(HS, groups, {}, {}), around_, unseen_, groups);
    // A layout that lacks few test rows downdates each row's terms by its
    // h S Π (Woodbury).
    const auto seen = HS.leftCols(observed_);
    row_terms_.hs_pi = seen * pi_;
    row_terms_.q = (row_terms_.hs_pi.array() * seen.array()).rowwise().sum().matrix() + unseen_;
  });
  return row_terms_;
}

void LatticeAnalysis::solve(Eigen::MatrixXd info, Eigen::MatrixXd spread) {
  info_ = std::move(info);
  spread_ = std::move(spread);
  pi_ = inverse_of_information(info_);
  // Π (I + J) Π is symmetric: its lower triangle, then mirrored.
  const Eigen::MatrixXd spread_pi = spread_ * pi_;
  around_.resize(pi_.rows(), pi_.cols());
  around_.triangularView<Eigen::Lower>() = pi_ * spread_pi;
  around_.triangularView<Eigen::StrictlyUpper>() = around_.transpose();
}

RunAnalyser::RunAnalyser(const Layout& layout, const GaussianModel& model) {
  const LatticeAnalysis own(layout, model);
  std::vector<Eigen::Index> rows(layout.rows.size());
  for (std::size_t i = 0; i < rows.size(); ++i) rows[i] = static_cast<Eigen::Index>(i);
  layout_ = &layout;
  finish(own, rows, own.pi_, own.row_terms().q, own.row_terms().ab, own.around_.diagonal());
}

RunAnalyser::RunAnalyser(const Layout& layout, const LatticeAnalysis& a, std::span<const Eigen::Index> rows) {
  layout_ = &layout;
  INSMC_ASSERT(rows.size() == layout.rows.size(), "{} rows for a layout of {}", rows.size(), layout.rows.size());
  // The lattice's test rows this layout lacks (rows_within keeps the stages apart).
  const auto nt = static_cast<std::size_t>(layout.test_rows);
  std::vector<Eigen::Index> missing;
  for (Eigen::Index m = 0, i = 0; m < a.test_rows_; ++m) {
    if (static_cast<std::size_t>(i) < nt && rows[static_cast<std::size_t>(i)] == m) ++i;
    else missing.push_back(m);
  }
  const auto k = static_cast<Eigen::Index>(missing.size());
  const Eigen::Index d = a.observed_;  // the lacked rows touch no cause beyond
  if (k == 0) {
    finish(a, rows, a.pi_, rows_of(a.row_terms().q, rows), rows_of(a.row_terms().ab, rows), a.around_.diagonal());
    return;
  }
  // Information of the layout = the lattice's − G Gᵀ, g_m = S h_mᵀ/σ_m of each
  // row m it lacks; Woodbury: Π_ℓ = Π + U C Uᵀ, U = Π G, C = (I − Gᵀ Π G)⁻¹.
  Eigen::MatrixXd G(d, k);
  Eigen::VectorXd share(k);
  for (Eigen::Index j = 0; j < k; ++j) {
    const Eigen::Index m = missing[static_cast<std::size_t>(j)];
    G.col(j) = a.s_.head(d).cwiseProduct(a.H_->row(m).head(d).transpose()) / std::sqrt(a.noise_var_[m]);
    share[j] = a.actual_noise_var_[m] / a.noise_var_[m];
  }
  std::vector<Eigen::Index> all(rows.size());
  for (std::size_t i = 0; i < all.size(); ++i) all[i] = static_cast<Eigen::Index>(i);
  const auto own_fit = [&] {
    // The rows the layout lacks held nearly all the information about some
    // cause: a downdate would cancel; the layout's fit is made anew.
    LatticeAnalysis own(layout, a, rows);
    own.fit(false);
    finish(own, all, own.pi_, own.q_, own.ab_, own.around_.diagonal());
  };
  if (static_cast<double>(k) > kDowndateShare * static_cast<double>(d)) {
    // Too many rows missing for Woodbury: the layout's information is the
    // lattice's less G Gᵀ (O(k d²) instead of a Gram over its test rows).
    const Eigen::VectorXd lacked = G.rowwise().squaredNorm();
    if (!((a.info_.diagonal() - lacked).array() > kLeastKeptInformation * a.info_.diagonal().array()).all()) {
      own_fit();
      return;
    }
    const LatticeAnalysis own(a, rows, G, share);
    finish(a, rows, own.pi_, own.q_, own.ab_, own.around_.diagonal());
    return;
  }
  const Eigen::MatrixXd U = a.pi_ * G;
  Eigen::MatrixXd kept = -G.transpose() * U;
  kept.diagonal().array() += 1.0;
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(kept);
  if (eig.info() != Eigen::Success || !(eig.eigenvalues().minCoeff() > kLeastKeptInformation)) {
    own_fit();
    return;
  }
  const Eigen::MatrixXd C =
      eig.eigenvectors() * eig.eigenvalues().cwiseInverse().asDiagonal() * eig.eigenvectors().transpose();
  const Eigen::MatrixXd spread_U = a.spread_ * U;
  const Eigen::MatrixXd W = U.transpose() * spread_U;
  // Per row with a = h S Π, b = a G, β = b C, e = a (I + J) U:
  //   q_ℓ  = q + β bᵀ,
  //   ab_ℓ = ab + 2 e βᵀ + β W βᵀ − Σ_m share_m β_m²  (h S Π_ℓ G = β).
  const auto update = [&](const Eigen::MatrixXd& a_rows, const Eigen::VectorXd& q, const Eigen::VectorXd& ab,
                          Eigen::VectorXd& q_out, Eigen::VectorXd& ab_out) {
    const Eigen::MatrixXd b = a_rows * G;
    const Eigen::MatrixXd beta = b * C;
    const Eigen::MatrixXd e = a_rows * spread_U;
    q_out = q + (beta.array() * b.array()).rowwise().sum().matrix();
    ab_out = ab + (2.0 * (e.array() * beta.array()).rowwise().sum() +
                   ((beta * W).array() * beta.array()).rowwise().sum()).matrix() -
             beta.array().square().matrix() * share;
  };
  Eigen::VectorXd q, ab, pi_diagonal, around_diagonal;
  const LatticeAnalysis::RowTerms& lattice_terms = a.row_terms();
  update(rows_of(lattice_terms.hs_pi, rows), rows_of(lattice_terms.q, rows), rows_of(lattice_terms.ab, rows), q, ab);
  // The causes themselves (h S = the unit vector of cause j): the diagonals
  // of Π_ℓ and of Π_ℓ (I + J_ℓ) Π_ℓ the estimates need.
  update(a.pi_, a.pi_.diagonal(), a.around_.diagonal(), pi_diagonal, around_diagonal);
  Eigen::MatrixXd pi = a.pi_ + U * C * U.transpose();
  pi.diagonal() = pi_diagonal;  // the same to round-off, formed as the rows' q are
  finish(a, rows, pi, q, ab, around_diagonal);
}

void RunAnalyser::finish(const LatticeAnalysis& a, std::span<const Eigen::Index> rows, const Eigen::MatrixXd& pi,
                         const Eigen::VectorXd& q, const Eigen::VectorXd& ab, const Eigen::VectorXd& around_diagonal) {
  const auto n = static_cast<Eigen::Index>(rows.size());
  test_rows_ = layout_->test_rows;
  const Eigen::Index nt = test_rows_;
  // The fit moves only the causes the test rows see (pi's): the others keep
  // their prior, so the estimate and each row's residual take those columns.
  const Eigen::Index p = pi.rows();
  mean_ = rows_of(a.mean_, rows);
  // The rows' model stays the lattice's, shared (not copied per layout).
  model_H_ = a.H_;
  rows_.assign(rows.begin(), rows.end());
  INSMC_ASSERT(std::adjacent_find(rows_.begin(), rows_.end(), std::greater_equal<>()) == rows_.end(),
               "a layout's rows in its lattice must ascend ({} rows)", rows_.size());
  causes_ = p;
  const Eigen::VectorXd noise_var = rows_of(a.noise_var_, rows), actual_noise_var = rows_of(a.actual_noise_var_, rows);
  inverse_test_noise_ = noise_var.head(nt).cwiseInverse();
  posterior_ = a.s_.head(p).asDiagonal() * pi * a.s_.head(p).asDiagonal();
  for (Eigen::Index c = 0; c < p; ++c) {
    const Eigen::Index j = a.active_[static_cast<std::size_t>(c)];
    if (j < uncertainty_slot::kDim && 1.0 - pi(c, c) > kResolvedShare) {
      estimate_columns_.push_back(static_cast<int>(c));
      estimate_x_.push_back(static_cast<int>(j));
    }
  }
  const auto m = static_cast<Eigen::Index>(estimate_columns_.size());
  expected_.resize(n);
  actual_.resize(n + m);
  for (Eigen::Index i = 0; i < n; ++i) {
    const double r = noise_var[i], ra = actual_noise_var[i];
    expected_[i] = i < nt ? std::max(r - q[i], 1e-6 * r) : q[i] + r;
    actual_[i] = std::max(0.0, i < nt ? ab[i] + ra * (1.0 - 2.0 * q[i] / r) : ab[i] + ra);
  }
  estimate_var_.resize(m);
  for (Eigen::Index k = 0; k < m; ++k) {
    const int c = estimate_columns_[static_cast<std::size_t>(k)];
    // P − P⁺ and P − 2P⁺ + A + B, over the prior (scaled).
    estimate_var_[k] = a.prior_[c] * (1.0 - pi(c, c));
    actual_[n + k] = std::max(0.0, (1.0 - 2.0 * pi(c, c) + around_diagonal[c]) / (1.0 - pi(c, c)));
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
  const auto layout_rows = static_cast<Eigen::Index>(rows_.size());
  INSMC_ASSERT(n >= test_rows_ && n <= layout_rows, "run of {} values for a layout of {} rows ({} test rows)", n,
               layout_rows, test_rows_);
  const auto m = static_cast<Eigen::Index>(estimate_columns_.size());
  // Over the model's rows up to the last the run has (its own among them):
  // the fit ĉ = P⁺ Hₜᵀ R⁻¹ yₜ, then each row's y − h ĉ.
  const Eigen::MatrixXd& H = *model_H_;
  const auto extent = [&](Eigen::Index k) {
    return k == 0 ? Eigen::Index{0} : *std::max_element(rows_.begin(), rows_.begin() + k) + 1;
  };
  const Eigen::Index test_extent = extent(test_rows_), run_extent = extent(n);
  Eigen::VectorXd weighted = Eigen::VectorXd::Zero(test_extent);
  for (Eigen::Index i = 0; i < test_rows_; ++i) weighted[rows_[static_cast<std::size_t>(i)]] = y[i] * inverse_test_noise_[i];
  const Eigen::VectorXd c = posterior_ * (H.topLeftCorner(test_extent, causes_).transpose() * weighted);
  const Eigen::VectorXd hc = H.topLeftCorner(run_extent, causes_) * c;
  Eigen::VectorXd v(n + m);
  for (Eigen::Index i = 0; i < n; ++i) v[i] = (y[i] - hc[rows_[static_cast<std::size_t>(i)]]) / std::sqrt(expected_[i]);
  for (Eigen::Index k = 0; k < m; ++k) v[n + k] = c[estimate_columns_[static_cast<std::size_t>(k)]] / std::sqrt(estimate_var_[k]);
  return v;
}

Eigen::MatrixXd RunAnalyser::estimate_map() const {
  const auto m = static_cast<Eigen::Index>(estimate_columns_.size());
  const Eigen::MatrixXd test_H =
      rows_of(*model_H_, std::span<const Eigen::Index>(rows_).first(static_cast<std::size_t>(test_rows_)), causes_);
  Eigen::MatrixXd W(m, test_rows_);
  for (Eigen::Index k = 0; k < m; ++k)
    W.row(k) = (test_H * posterior_.row(estimate_columns_[static_cast<std::size_t>(k)]).transpose())
                   .cwiseProduct(inverse_test_noise_)
                   .transpose() /
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
