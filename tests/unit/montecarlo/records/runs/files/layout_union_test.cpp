// Layouts that miss records, each its own way, take their rows from the
// union of the file's layouts (montecarlo/records/runs/files/layout_union.h): the
// rows are found where they are, and a model built on the union and cut to
// a layout's rows is the layout's own.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <random>

#include "lib/uncertainty/uncertainty_model.h"
#include "montecarlo/records/runs/model/gaussian_model.h"
#include "montecarlo/records/runs/model/run_analysis.h"
#include "montecarlo/records/runs/files/layout_union.h"
#include "tests/unit/montecarlo/records/runs/test_layout.h"

namespace insmc::runs {
namespace {

/// The test layout with every `step`-th f record from `first` dropped
/// (three axes at a time), as a logger that loses samples writes it.
Layout with_dropouts(const Layout& full, int first, int step) {
  Layout l = full;
  l.rows.clear();
  l.test_rows = 0;
  int f_record = 0;
  for (std::size_t i = 0; i < full.rows.size(); ++i) {
    const ObservationRow& r = full.rows[i];
    const bool dropped = r.quantity == Quantity::kF && f_record >= first && (f_record - first) % step == 0;
    if (r.quantity == Quantity::kF && r.axis == 2) ++f_record;
    if (dropped) continue;
    l.rows.push_back(r);
    if (static_cast<int>(i) < full.test_rows) ++l.test_rows;
  }
  return l;
}

/// The test layout with every second f record of its test run missing
/// (those at multiples of 20 s).
Layout every_second_test_f_missing(const Layout& full) {
  Layout sparse = full;
  sparse.rows.clear();
  sparse.test_rows = 0;
  for (int i = 0; i < static_cast<int>(full.rows.size()); ++i) {
    const ObservationRow& r = full.rows[static_cast<std::size_t>(i)];
    if (i < full.test_rows && r.quantity == Quantity::kF && std::fmod(r.t_s, 20.0) == 0.0) continue;
    sparse.rows.push_back(r);
    if (i < full.test_rows) ++sparse.test_rows;
  }
  return sparse;
}

TEST(LayoutUnion, EachLayoutFindsItsRowsInTheUnion) {
  const Layout full = testing::test_layout(3600.0);
  const Layout a = with_dropouts(full, 3, 17), b = with_dropouts(full, 8, 23);
  const Layout shorter = with_dropouts(testing::test_layout(1800.0), 5, 11);
  const Layout* layouts[] = {&a, &b, &shorter};
  const Layout lattice = layout_union(layouts);
  // Together they miss no record of the full layout.
  EXPECT_EQ(lattice, full);
  for (const Layout* l : layouts) {
    const auto rows = rows_within(*l, lattice);
    ASSERT_TRUE(rows.has_value());
    ASSERT_EQ(rows->size(), l->rows.size());
    for (std::size_t i = 0; i < rows->size(); ++i) EXPECT_EQ(lattice.rows[static_cast<std::size_t>((*rows)[i])], l->rows[i]);
  }
  // A row the lattice lacks, or one of another stage, is not within it.
  Layout extra = a;
  extra.rows.push_back({3605.0, Quantity::kR, 0, extra.rows.back().group});
  EXPECT_FALSE(rows_within(extra, a).has_value());
  EXPECT_FALSE(rows_within(full, a).has_value());
  Layout moved = a;
  moved.test_rows -= 3;
  EXPECT_FALSE(rows_within(moved, lattice).has_value());
}

TEST(LayoutUnion, TheUnionsModelCutToALayoutIsTheLayoutsOwn) {
  const Layout full = testing::test_layout(3600.0);
  const Layout a = with_dropouts(full, 2, 9);
  // Continuous f: pulse counting's columns are the leading components of
  // the rows' covariance and differ with the rows they are taken over; the
  // rest of the model is each row's own.
  RecordSite s = testing::test_site();
  s.dv_pulse_mps = 0.0;
  const UncertaintyVector x_var = UncertaintyModel{}.variance();
  const BaseModel on_lattice = make_base_model(full, s, x_var);
  const auto rows = rows_within(a, full);
  ASSERT_TRUE(rows.has_value());
  const GaussianModel cut = combine(select_rows(on_lattice, *rows), {});
  const GaussianModel own = combine(make_base_model(a, s, x_var), {});
  ASSERT_EQ(cut.H.rows(), own.H.rows());
  ASSERT_EQ(cut.H.cols(), own.H.cols());
  EXPECT_LT((cut.H - own.H).cwiseAbs().maxCoeff(), 1e-9 * own.H.cwiseAbs().maxCoeff());
  EXPECT_LT((cut.noise_var - own.noise_var).cwiseAbs().maxCoeff(), 1e-9 * own.noise_var.maxCoeff());
  const RunAnalyser from_lattice(a, cut), from_own(a, own);
  std::mt19937_64 rng(7);
  std::normal_distribution<double> n01;
  for (int draw = 0; draw < 3; ++draw) {
    Eigen::VectorXd c(own.prior_var.size()), e(own.H.rows());
    for (Eigen::Index j = 0; j < c.size(); ++j) c[j] = std::sqrt(own.prior_var[j]) * n01(rng);
    for (Eigen::Index i = 0; i < e.size(); ++i) e[i] = std::sqrt(own.noise_var[i]) * n01(rng);
    const Eigen::VectorXd y = own.H * c + e;
    const GroupSums x = from_lattice.analyse(y), z = from_own.analyse(y);
    for (int g = 0; g < kGroupCount; ++g) {
      EXPECT_EQ(x.count[g], z.count[g]) << group_name(g);
      EXPECT_NEAR(x.z2[g], z.z2[g], 1e-7 * (1.0 + z.z2[g])) << group_name(g);
      EXPECT_NEAR(x.expected[g], z.expected[g], 1e-7 * (1.0 + z.expected[g])) << group_name(g);
    }
  }
}

/// The group sums of `a` and `b` on draws from `model` agree to round-off.
void expect_same_sums(const RunAnalyser& a, const RunAnalyser& b, const GaussianModel& model, int seed) {
  std::mt19937_64 rng(static_cast<std::uint64_t>(seed));
  std::normal_distribution<double> n01;
  for (int draw = 0; draw < 3; ++draw) {
    Eigen::VectorXd c(model.prior_var.size()), e(model.H.rows());
    for (Eigen::Index j = 0; j < c.size(); ++j) c[j] = std::sqrt(model.prior_var[j]) * n01(rng);
    for (Eigen::Index i = 0; i < e.size(); ++i) e[i] = std::sqrt(model.noise_var[i]) * n01(rng);
    const Eigen::VectorXd y = model.H * c + e;
    const GroupSums x = a.analyse(y), z = b.analyse(y);
    for (int g = 0; g < kGroupCount; ++g) {
      EXPECT_EQ(x.count[g], z.count[g]) << group_name(g);
      EXPECT_NEAR(x.z2[g], z.z2[g], 1e-7 * (1.0 + z.z2[g])) << group_name(g);
      EXPECT_NEAR(x.expected[g], z.expected[g], 1e-7 * (1.0 + z.expected[g])) << group_name(g);
      EXPECT_NEAR(x.floor[g], z.floor[g], 1e-7 * (1.0 + z.floor[g])) << group_name(g);
    }
  }
}

TEST(LayoutUnion, ALayoutsFitCutFromTheLatticesIsItsOwn) {
  // The lattice's fit downdated by the test rows a layout lacks (Woodbury,
  // run_analysis.h) against the layout's fit made anew; and a layout that
  // lacks most of the test run, fitted on its own rows.
  // Pulses of 0.1 ft/s: the f rows' counting noise. (A continuous f has
  // only the 0.1 µg floor, and a test residual's normalizer σ² − h P⁺ hᵀ
  // then cancels to a part in 10⁴ of σ²: two fits that agree to 10⁻⁸ in P⁺
  // differ there by 10⁻⁴, whichever way each is made.)
  const Layout full = testing::test_layout(3600.0);
  const RecordSite s = testing::test_site();
  const UncertaintyVector x_var = UncertaintyModel{}.variance();
  const GaussianModel on_lattice = combine(make_base_model(full, s, x_var), {});
  const LatticeAnalysis shared(full, on_lattice);
  const Layout sparse = every_second_test_f_missing(full);
  // No r record in the test run: the causes only r sees (the position
  // offsets) lose nearly all their information, so the lattice's less the
  // rows lacked would cancel, and the layout is fitted anew.
  Layout without_r = full;
  without_r.rows.clear();
  without_r.test_rows = 0;
  for (int i = 0; i < static_cast<int>(full.rows.size()); ++i) {
    const ObservationRow& r = full.rows[static_cast<std::size_t>(i)];
    if (i < full.test_rows && r.quantity == Quantity::kR) continue;
    without_r.rows.push_back(r);
    if (i < full.test_rows) ++without_r.test_rows;
  }
  {
    // Each cause's information (scaled, with the prior's 1) from all test
    // rows and from those without_r keeps: some cause keeps under
    // kLeastKeptInformation, so the layout is not the lattice's less its rows.
    double least_kept = 1.0;
    for (Eigen::Index j = 0; j < on_lattice.H.cols(); ++j) {
      if (!(on_lattice.prior_var[j] > 0)) continue;
      double all = 1.0, kept = 1.0;
      for (Eigen::Index i = 0; i < full.test_rows; ++i) {
        const double w = on_lattice.prior_var[j] * on_lattice.H(i, j) * on_lattice.H(i, j) / on_lattice.noise_var[i];
        all += w;
        if (full.rows[static_cast<std::size_t>(i)].quantity != Quantity::kR) kept += w;
      }
      least_kept = std::min(least_kept, kept / all);
    }
    ASSERT_LT(least_kept, kLeastKeptInformation) << "the layout must be one the downdate would cancel on";
  }
  int seed = 11;
  for (const Layout& l : {with_dropouts(full, 5, 60), with_dropouts(full, 0, 40), sparse, without_r, full}) {
    const auto rows = rows_within(l, full);
    ASSERT_TRUE(rows.has_value());
    const GaussianModel own_model = select_rows(on_lattice, *rows);
    SCOPED_TRACE(::testing::Message() << l.test_rows << " of " << full.test_rows << " test rows");
    expect_same_sums(RunAnalyser(l, shared, *rows), RunAnalyser(l, own_model), own_model, seed++);
  }
}

TEST(LayoutUnion, AnAnalyserCutFromALatticeOutlivesItAndTakesARunThatStoppedEarly) {
  // The analyser shares the lattice's rows' model, not the lattice: it is
  // used after the lattice is gone (as the diagnosis keeps its analysers),
  // and a run holding only the layout's first rows gets the sums of those
  // rows (the same fit: the same test rows).
  const Layout full = testing::test_layout(3600.0);
  const RecordSite s = testing::test_site();
  const UncertaintyVector x_var = UncertaintyModel{}.variance();
  const GaussianModel on_lattice = combine(make_base_model(full, s, x_var), {});
  const Layout sparse = every_second_test_f_missing(full);
  const auto rows = rows_within(sparse, full);
  ASSERT_TRUE(rows.has_value());
  std::optional<RunAnalyser> cut;
  {
    const LatticeAnalysis shared(full, on_lattice);
    cut.emplace(sparse, shared, *rows);
  }
  const GaussianModel own_model = select_rows(on_lattice, *rows);
  const RunAnalyser own(sparse, own_model);
  std::mt19937_64 rng(29);
  std::normal_distribution<double> n01;
  const Eigen::Index n = sparse.test_rows + (static_cast<Eigen::Index>(sparse.rows.size()) - sparse.test_rows) / 2;
  for (const Eigen::Index length : {static_cast<Eigen::Index>(sparse.rows.size()), n, Eigen::Index{sparse.test_rows}}) {
    SCOPED_TRACE(::testing::Message() << length << " of " << sparse.rows.size() << " rows");
    Eigen::VectorXd c(own_model.prior_var.size()), e(own_model.H.rows());
    for (Eigen::Index j = 0; j < c.size(); ++j) c[j] = std::sqrt(own_model.prior_var[j]) * n01(rng);
    for (Eigen::Index i = 0; i < e.size(); ++i) e[i] = std::sqrt(own_model.noise_var[i]) * n01(rng);
    const Eigen::VectorXd y = (own_model.H * c + e).head(length);
    const GroupSums x = cut->analyse(y), z = own.analyse(y);
    for (int g = 0; g < kGroupCount; ++g) {
      EXPECT_EQ(x.count[g], z.count[g]) << group_name(g);
      EXPECT_NEAR(x.z2[g], z.z2[g], 1e-7 * (1.0 + z.z2[g])) << group_name(g);
      EXPECT_NEAR(x.expected[g], z.expected[g], 1e-7 * (1.0 + z.expected[g])) << group_name(g);
    }
    double rows_counted = 0.0;
    for (int g = 0; g < kGroupCount; ++g)
      if (g != kEstimatesGroup) rows_counted += x.count[g];
    EXPECT_EQ(rows_counted, static_cast<double>(length));
  }
  const Eigen::MatrixXd map_cut = cut->estimate_map(), map_own = own.estimate_map();
  ASSERT_EQ(map_cut.rows(), map_own.rows());
  ASSERT_EQ(map_cut.cols(), map_own.cols());
  EXPECT_LT((map_cut - map_own).cwiseAbs().maxCoeff(), 1e-7 * (1.0 + map_own.cwiseAbs().maxCoeff()));
}

TEST(LayoutUnion, PulseCountingKeepsEachRowsVariance) {
  // With pulses, the counting's columns differ with the rows they are
  // taken over, but each row's total variance (columns and rest) is its own.
  const Layout full = testing::test_layout(3600.0);
  const Layout a = with_dropouts(full, 4, 13);
  const RecordSite s = testing::test_site();
  const UncertaintyVector x_var = UncertaintyModel{}.variance();
  const auto rows = rows_within(a, full);
  ASSERT_TRUE(rows.has_value());
  const BaseModel cut = select_rows(make_base_model(full, s, x_var), *rows);
  const BaseModel own = make_base_model(a, s, x_var);
  const Eigen::VectorXd var_cut = cut.counting.columns.rowwise().squaredNorm() + cut.counting.noise_var;
  const Eigen::VectorXd var_own = own.counting.columns.rowwise().squaredNorm() + own.counting.noise_var;
  EXPECT_LT((var_cut - var_own).cwiseAbs().maxCoeff(), 1e-6 * var_own.maxCoeff());
}

/// Each row's expected square from the dense posterior over every cause,
/// written out (run_analysis.h), scaled by S = diag(√prior):
/// Π = (I + S Hₜᵀ R⁻¹ Hₜ S)⁻¹, q = h S Π S hᵀ, under the model's noise
/// σ² − q on test rows and q + σ² after them; under the actual noise, with
/// J = S Hₜᵀ R⁻¹ R_a R⁻¹ Hₜ S and ab = h S Π (I + J) Π S hᵀ,
/// ab + R_a (1 − 2q/σ²) on test rows and ab + R_a after them.
struct DenseSquares {
  Eigen::VectorXd expected, actual;
  double round_off = 0;  ///< the relative round-off of a posterior: 10 κ(I + S Hₜᵀ R⁻¹ Hₜ S) ε
  /// The size of each row's terms, on which the round-off acts: of the
  /// quadratic forms |h S|² max(1, ‖Π (I + J) Π‖) (a form much smaller
  /// than that is a cancellation), and R_a (1 + 2q/σ²).
  Eigen::VectorXd terms;
};
DenseSquares dense_squares(const GaussianModel& m, int test_rows) {
  const Eigen::VectorXd s = m.prior_var.cwiseSqrt();
  const Eigen::MatrixXd HS = m.H * s.asDiagonal();
  const Eigen::MatrixXd Ht = HS.topRows(test_rows);
  const Eigen::VectorXd w = m.noise_var.head(test_rows).cwiseInverse();
  Eigen::MatrixXd info = Ht.transpose() * w.asDiagonal() * Ht;
  info.diagonal().array() += 1.0;
  const Eigen::MatrixXd pi = info.llt().solve(Eigen::MatrixXd::Identity(info.rows(), info.cols()));
  const Eigen::VectorXd eig = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(info).eigenvalues();
  const double round_off = 10.0 * eig.maxCoeff() / eig.minCoeff() * std::numeric_limits<double>::epsilon();
  Eigen::MatrixXd spread = Ht.transpose() * (m.actual_noise_var.head(test_rows).cwiseProduct(w.cwiseAbs2())).asDiagonal() * Ht;
  spread.diagonal().array() += 1.0;
  const Eigen::MatrixXd around = pi * spread * pi;
  const double around_norm = std::max(1.0, Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(around).eigenvalues().cwiseAbs().maxCoeff());
  DenseSquares d{Eigen::VectorXd(m.H.rows()), Eigen::VectorXd(m.H.rows()), round_off, Eigen::VectorXd(m.H.rows())};
  for (Eigen::Index i = 0; i < m.H.rows(); ++i) {
    const double q = HS.row(i) * pi * HS.row(i).transpose(), ab = HS.row(i) * around * HS.row(i).transpose();
    const double r = m.noise_var[i], ra = m.actual_noise_var[i];
    d.expected[i] = i < test_rows ? r - q : q + r;
    d.actual[i] = i < test_rows ? ab + ra * (1.0 - 2.0 * q / r) : ab + ra;
    d.terms[i] = HS.row(i).squaredNorm() * around_norm + ra * (1.0 + (i < test_rows ? 2.0 * std::abs(q) / r : 0.0));
  }
  return d;
}

TEST(LayoutUnion, CausesNoTestRowSeesKeepTheirPriorAndTheRowsTheirWholeVariance) {
  // A run model with causes that act only after the test run (a process'
  // later knots: ramps that start after T), one of them before a cause the
  // test rows do see. The fit is made over the causes the test rows touch
  // (run_analysis.h); each row's expected square must be the dense
  // posterior's over every cause, on the layout's own fit and on one cut
  // from the lattice (Woodbury), nav rows included (they carry the unseen
  // causes' whole prior).
  const Layout full = testing::test_layout(3600.0);
  const RecordSite s = testing::test_site();
  GaussianModel m = combine(make_base_model(full, s, UncertaintyModel{}.variance()), {});
  const double T = full.rows[static_cast<std::size_t>(full.test_rows - 1)].t_s;
  const Eigen::Index d = m.H.cols(), extra = 8;
  m.H.conservativeResize(Eigen::NoChange, d + extra);
  m.prior_var.conservativeResize(d + extra);
  for (Eigen::Index j = 0; j < extra; ++j) {
    // Column d + 1 is seen by the test rows (it starts at 300 s); the others start after T.
    const double start = j == 1 ? 300.0 : T + 150.0 * static_cast<double>(j + 1);
    for (Eigen::Index i = 0; i < m.H.rows(); ++i) {
      const ObservationRow& r = full.rows[static_cast<std::size_t>(i)];
      const double after = std::max(0.0, r.t_s - start);
      m.H(i, d + j) = after > 0 ? (r.quantity == Quantity::kR ? 0.01 * after : 1e-5) : 0.0;
    }
    m.prior_var[d + j] = 1.0 + static_cast<double>(j);
  }
  const auto expect_dense = [](const RunAnalyser& a, const GaussianModel& model, int test_rows) {
    const DenseSquares want = dense_squares(model, test_rows);
    ASSERT_EQ(a.expected_square().size(), want.expected.size());
    ASSERT_GE(a.actual_square().size(), want.actual.size());  // then the estimates
    for (Eigen::Index i = 0; i < want.expected.size(); ++i) {
      const double r = model.noise_var[i];
      // Both ways round off as the posterior's condition number allows.
      const double tol = std::max(1e-9, want.round_off);
      EXPECT_NEAR(a.expected_square()[i], want.expected[i], tol * (want.terms[i] + r)) << "row " << i;
      EXPECT_NEAR(a.actual_square()[i], std::max(0.0, want.actual[i]), tol * (want.terms[i] + r)) << "row " << i;
    }
  };
  expect_dense(RunAnalyser(full, m), m, full.test_rows);
  const LatticeAnalysis shared(full, m);
  // Few test rows lacked (Woodbury), and every second f record of the test
  // run lacked (the lattice's information less the rows').
  const Layout sparse = every_second_test_f_missing(full);
  for (const Layout& l : {with_dropouts(full, 5, 60), with_dropouts(full, 0, 40), sparse}) {
    const auto rows = rows_within(l, full);
    ASSERT_TRUE(rows.has_value());
    const GaussianModel own = select_rows(m, *rows);
    SCOPED_TRACE(::testing::Message() << l.test_rows << " of " << full.test_rows << " test rows");
    expect_dense(RunAnalyser(l, shared, *rows), own, l.test_rows);
    expect_dense(RunAnalyser(l, own), own, l.test_rows);
  }
}

}  // namespace
}  // namespace insmc::runs
