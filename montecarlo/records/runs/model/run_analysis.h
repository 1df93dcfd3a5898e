#pragma once
/// One run against a GaussianModel (gaussian_model.h), the way the report's
/// preflight procedure uses the data: the test-run rows are fitted (linear
/// minimum-variance estimate of the causes c with the prior), then the
/// navigation rows are predicted from that fit. Each row gets a normalized
/// square z² whose expectation under the model is exactly 1, whatever the
/// distribution (only second moments enter):
///   test rows:  residual e = y − H ĉ,   E e² = σ² − h P⁺ hᵀ;
///   nav rows:   innovation ν = y − H ĉ, E ν² = h P⁺ hᵀ + σ²;
///   estimates:  ĉ_j of x,               E ĉ_j² = P_jj − P⁺_jj,
/// P⁺ the posterior covariance. Sums per report group (layout.h) are what the
/// gap metric aggregates over runs.
///
/// The fit weights rows by the model's noise_var, which carries a
/// model-error floor (gaussian_model.h); the data carry only
/// actual_noise_var. So each row also gets the expectation of its square
/// under the actual noise with that same (floor-weighted) fit, E_i: with
/// A = P⁺P⁻¹P⁺, B = K R_a Kᵀ, K = P⁺Hₜᵀ R⁻¹ (the fit's gain), q = h P⁺ hᵀ,
///   test rows:  E_i = h (A + B) hᵀ + R_a,i (1 − 2 q_i / R_i),
///   nav rows:   E_i = h (A + B) hᵀ + R_a,i,
///   estimates:  E_j = P_jj − 2 P⁺_jj + A_jj + B_jj,
/// which reduce to the normalizers above when R_a = R. E_i is affine in the
/// noise, so e_i − E_i ≥ 0 is what the floor alone contributes. The group
/// sums carry Σ E_i/e_i and Σ (1 − E_i/e_i): the metric compares Σ z² with
/// the first plus the share of the second that the null shows to be real
/// model error (gap_metric.h).
#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <array>
#include <memory>
#include <mutex>
#include <span>
#include <vector>

#include "montecarlo/records/runs/model/gaussian_model.h"
#include "montecarlo/records/runs/model/row_column_groups.h"

namespace insmc::runs {

/// Per group, over its terms i (rows, or estimates): Σ z², their number,
/// Σ E_i/e_i (the expected Σ z² under the actual noise) and Σ (1 − E_i/e_i)
/// (what the model-error floor adds to it).
struct GroupSums {
  std::array<double, kGroupCount> z2{};
  std::array<double, kGroupCount> count{};
  std::array<double, kGroupCount> expected{};
  std::array<double, kGroupCount> floor{};
  GroupSums& operator+=(const GroupSums& o) {
    for (int g = 0; g < kGroupCount; ++g)
      z2[g] += o.z2[g], count[g] += o.count[g], expected[g] += o.expected[g], floor[g] += o.floor[g];
    return *this;
  }
};

/// An estimate counts in the "estimates vs prior" group when the test run
/// removes at least this share of its prior variance.
inline constexpr double kResolvedShare = 0.1;

/// A layout cut from a lattice takes the lattice's information less the
/// rows it lacks while every cause keeps more than this share of its own
/// (and the downdate's remainder every eigenvalue above it: a cancellation
/// of at most 1/kLeastKeptInformation); otherwise it is fitted on its own.
inline constexpr double kLeastKeptInformation = 1e-3;

/// What every layout cut from one lattice (layout_union.h) shares of its
/// analysis: the lattice model's fit over all its test rows. A layout that
/// lacks k of those test rows has the information of the lattice less a
/// rank-k term, so its posterior and each row's expected squares follow
/// from the lattice's by Woodbury's identity at O(rows × causes × k)
/// instead of O(rows × causes²) (docs/gap-method.md §1, "Runs that miss
/// records").
class LatticeAnalysis {
 public:
  LatticeAnalysis(const Layout& lattice, const GaussianModel& model);

 private:
  friend class RunAnalyser;
  /// The model of `layout`, the rows `rows` of `lattice`'s, not yet fitted
  /// (fit() fits it anew).
  LatticeAnalysis(const Layout& layout, const LatticeAnalysis& lattice, std::span<const Eigen::Index> rows);
  /// The fit of the layout of the lattice's rows `rows`, from the lattice's
  /// information less that of the test rows it lacks (G's columns
  /// g_m = S h_mᵀ/σ_m, `share` their R_a/R): its Π, Π (I + J) Π and the
  /// rows' q and ab only; the rows' model stays the lattice's (finish takes
  /// it with `rows`).
  LatticeAnalysis(const LatticeAnalysis& lattice, std::span<const Eigen::Index> rows, const Eigen::MatrixXd& G,
                  const Eigen::VectorXd& share);
  /// The information and the spread from the test rows, then solve(); a
  /// layout fitted on its own also forms its rows' terms, a lattice keeps
  /// its rows' groups (its layouts' are theirs) and forms its rows' terms
  /// when a layout first asks (row_terms).
  void fit(bool lattice);
  /// Π and Π (I + J) Π from the scaled information I + S Hₜᵀ R⁻¹ Hₜ S and
  /// spread I + J (the rows' q and ab are then their forms, each group of
  /// rows over the causes it sees: row_column_groups.h).
  void solve(Eigen::MatrixXd info, Eigen::MatrixXd spread);
  /// The groups of the lattice's rows `rows` (their rows numbered 0, 1, ...).
  RowColumnGroups groups_of(std::span<const Eigen::Index> rows) const;

  const Layout* layout_;
  Eigen::VectorXd mean_;              // rows
  std::shared_ptr<const Eigen::MatrixXd> H_;  // rows × active causes (its layouts' analysers share it)
  Eigen::VectorXd prior_, s_;         // active: prior variance and its root (the scaling)
  std::vector<Eigen::Index> active_;  // the model's column of each active cause
  Eigen::VectorXd noise_var_, actual_noise_var_;  // rows
  int test_rows_ = 0;
  // The leading active causes the test rows touch (observed_columns); the
  // matrices below are theirs, the identity beyond (a cause no test row
  // sees keeps its prior). Scaled (c = S u): the information
  // I + S Hₜᵀ R⁻¹ Hₜ S, Π its inverse, the spread I + J of the actual test
  // noise through the fit, and Π (I + J) Π.
  Eigen::Index observed_ = 0;
  Eigen::MatrixXd info_, pi_, spread_, around_;
  Eigen::VectorXd unseen_;            // rows: |h S|² over the causes no test row sees (their Π is I)
  Eigen::VectorXd q_, ab_;            // a layout's rows: h Π hᵀ and h Π (I + J) Π hᵀ (scaled)
  RowColumnGroups groups_;            // a lattice's: the columns of each group of its rows
  std::vector<int> group_of_row_;     // a lattice's: each row's group

  /// A lattice's rows' terms, which its layouts that lack no test row or
  /// few take (Woodbury): H S Π (rows × observed), q and ab as above. Made
  /// once, when a layout first asks: a file whose every layout lacks many
  /// test rows never needs them.
  struct RowTerms {
    Eigen::MatrixXd hs_pi;
    Eigen::VectorXd q, ab;
  };
  const RowTerms& row_terms() const;
  mutable std::once_flag row_terms_once_;
  mutable RowTerms row_terms_;
};

class RunAnalyser {
 public:
  RunAnalyser(const Layout& layout, const GaussianModel& model);
  /// The analyser of `layout`, whose rows are the rows `rows` of the lattice
  /// `shared` was made on (rows_within): the same values as one made on the
  /// lattice model's rows `rows`, to round-off.
  RunAnalyser(const Layout& layout, const LatticeAnalysis& shared, std::span<const Eigen::Index> rows);

  /// Group sums of one run's values (layout order). A run may hold the
  /// first rows of the layout only (it stopped early; at least the test
  /// rows): every result is then that of those rows.
  GroupSums analyse(const Eigen::VectorXd& y) const;
  /// As analyse, also giving z (the signed normalized residual/innovation per row).
  GroupSums analyse(const Eigen::VectorXd& y, Eigen::VectorXd& z) const;

  /// The run's normalized values: z per row, then each resolved estimate
  /// over its expected std (the terms of the group sums). Affine in the data:
  /// normalized(y) = normalized_linear(y − model mean).
  Eigen::VectorXd normalized(const Eigen::VectorXd& data) const;
  Eigen::VectorXd normalized_linear(const Eigen::VectorXd& y) const;
  /// Group sums of normalized values.
  GroupSums sums_of(const Eigen::VectorXd& normalized_values) const;

  /// Expected square of each row's residual (test) or innovation (nav)
  /// under the model's own noise: the normalizer e_i.
  const Eigen::VectorXd& expected_square() const { return expected_; }
  /// The same under the actual noise, E_i (rows, then resolved estimates
  /// over their normalizers).
  const Eigen::VectorXd& actual_square() const { return actual_; }
  /// The x column (catalogue index) of each resolved estimate, in the order
  /// the normalized values list them after the rows.
  const std::vector<int>& estimate_x_columns() const { return estimate_x_; }
  /// The linear map from the test rows (less the model's mean) to the
  /// resolved estimates over their expected std, the tail of
  /// normalized_linear (estimates × test rows): what a signature or a
  /// covariance added to the test rows does to the estimates.
  Eigen::MatrixXd estimate_map() const;
  int test_rows() const { return test_rows_; }

 private:
  /// The rest of the analysis from the fit's scaled posterior Π, each
  /// row's q and ab (as LatticeAnalysis), and the diagonal of Π (I + J) Π.
  void finish(const LatticeAnalysis& a, std::span<const Eigen::Index> rows, const Eigen::MatrixXd& pi,
              const Eigen::VectorXd& q, const Eigen::VectorXd& ab, const Eigen::VectorXd& around_diagonal);

  const Layout* layout_;
  Eigen::VectorXd mean_;          // rows
  // The model's rows × active causes, shared with the lattice the layout
  // is cut from: its rows rows_, the first causes_ columns (the causes the
  // fit sees; the rest keep their prior mean 0).
  std::shared_ptr<const Eigen::MatrixXd> model_H_;
  std::vector<Eigen::Index> rows_;
  Eigen::Index causes_ = 0;
  Eigen::VectorXd inverse_test_noise_;  // test rows: 1/σ²
  Eigen::MatrixXd posterior_;     // P⁺ of those causes
  Eigen::VectorXd expected_;      // rows
  Eigen::VectorXd actual_;        // rows + estimates
  std::vector<int> estimate_columns_;  // active indices of resolved x
  std::vector<int> estimate_x_;        // their catalogue indices
  Eigen::VectorXd estimate_var_;
  Eigen::VectorXd share_;         // rows + estimates: min(1, E_i/e_i), the data-independent part of the sums
  int test_rows_ = 0;
};

}  // namespace insmc::runs
