// The rows grouped by the causes they see: each group's forms over its own
// columns against the forms over every column.
#include "montecarlo/records/runs/model/row_column_groups.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "montecarlo/records/runs/model/quadratic_forms.h"

namespace insmc::runs {
namespace {

/// Rows of `d` columns in `patterns` patterns (row i takes pattern i mod
/// patterns): pattern p leaves out every column c with (c + p) % 3 == 0 and
/// column d − p (so that no two are alike), pattern 0 every column; the
/// other entries drawn N(0, 1).
Eigen::MatrixXd patterned_rows(Eigen::Index rows, Eigen::Index d, int patterns, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> n01;
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(rows, d);
  for (Eigen::Index i = 0; i < rows; ++i) {
    const auto p = static_cast<int>(i % patterns);
    if (p == 0) continue;
    for (Eigen::Index c = 0; c < d; ++c)
      if ((c + p) % 3 != 0 && c != d - p) a(i, c) = n01(rng);
  }
  return a;
}

Eigen::MatrixXd symmetric_positive(Eigen::Index d, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> n01;
  Eigen::MatrixXd b(d, d);
  for (Eigen::Index j = 0; j < d; ++j)
    for (Eigen::Index i = 0; i < d; ++i) b(i, j) = n01(rng);
  return b * b.transpose();
}

TEST(RowColumnGroups, EachGroupsFormsOverItsColumnsAreTheFormsOverEveryColumn) {
  constexpr Eigen::Index d = 40, rows = 300;
  const Eigen::MatrixXd a = patterned_rows(rows, d, 6, 7);
  const Eigen::MatrixXd m = symmetric_positive(d, 8);
  const RowColumnGroups g = group_rows_by_columns(a, d);
  ASSERT_EQ(g.rows.size(), 6u);
  // Pattern 0 sees no column: its group has none, its forms are 0.
  std::size_t rows_seen = 0;
  for (std::size_t k = 0; k < g.rows.size(); ++k) {
    rows_seen += g.rows[k].size();
    for (Eigen::Index i : g.rows[k])
      for (Eigen::Index c = 0; c < d; ++c) {
        const bool listed = std::find(g.columns[k].begin(), g.columns[k].end(), c) != g.columns[k].end();
        EXPECT_EQ(listed, a(i, c) != 0.0) << "row " << i << " column " << c;
      }
  }
  EXPECT_EQ(rows_seen, static_cast<std::size_t>(rows));
  const Eigen::VectorXd grouped = grouped_row_quadratic_forms(group_blocks(a, g, {}, {}), m, g, rows);
  const Eigen::VectorXd dense = row_quadratic_forms(a, m);
  for (Eigen::Index i = 0; i < rows; ++i) {
    // Round-off of d² terms of size |a|² |m|: the bound of their sum.
    const double scale = (a.row(i).cwiseAbs() * m.cwiseAbs() * a.row(i).cwiseAbs().transpose())(0, 0);
    EXPECT_NEAR(grouped[i], dense[i], 4.0 * d * d * 1.1e-16 * scale + 1e-300) << "row " << i;
    if (i % 6 == 0) {
      EXPECT_EQ(grouped[i], 0.0);
    }
  }
}

TEST(RowColumnGroups, RowsCutAndColumnsScaledAreGatheredInOnePass) {
  // The blocks of rows {5, 2, 9} of A with each column scaled are those of
  // the matrix cut and scaled first.
  constexpr Eigen::Index d = 12;
  const Eigen::MatrixXd a = patterned_rows(12, d, 3, 11);
  const std::vector<Eigen::Index> rows = {5, 2, 9};
  Eigen::VectorXd scale(d);
  for (Eigen::Index c = 0; c < d; ++c) scale[c] = 0.5 + static_cast<double>(c);
  Eigen::MatrixXd cut(3, d);
  for (Eigen::Index i = 0; i < 3; ++i) cut.row(i) = a.row(rows[static_cast<std::size_t>(i)]).cwiseProduct(scale.transpose());
  const RowColumnGroups g = group_rows_by_columns(cut, d);
  const std::vector<Eigen::MatrixXd> from_source = group_blocks(a, g, rows, scale);
  const std::vector<Eigen::MatrixXd> from_cut = group_blocks(cut, g, {}, {});
  ASSERT_EQ(from_source.size(), from_cut.size());
  for (std::size_t k = 0; k < from_cut.size(); ++k) EXPECT_EQ(from_source[k], from_cut[k]) << "group " << k;
}

TEST(RowColumnGroups, MorePatternsThanTheBoundAreOneGroupOverEveryColumn) {
  constexpr Eigen::Index d = 70;  // more than one word of the pattern
  std::mt19937_64 rng(3);
  std::bernoulli_distribution half(0.5);
  Eigen::MatrixXd a(200, d);
  for (Eigen::Index i = 0; i < a.rows(); ++i)
    for (Eigen::Index c = 0; c < d; ++c) a(i, c) = half(rng) ? 1.0 + static_cast<double>(c) : 0.0;
  const RowColumnGroups g = group_rows_by_columns(a, d);
  ASSERT_EQ(g.rows.size(), 1u);
  EXPECT_EQ(g.rows[0].size(), 200u);
  EXPECT_EQ(g.columns[0].size(), static_cast<std::size_t>(d));
  const Eigen::MatrixXd m = symmetric_positive(d, 5);
  const Eigen::VectorXd grouped = grouped_row_quadratic_forms(group_blocks(a, g, {}, {}), m, g, a.rows());
  EXPECT_EQ(grouped, row_quadratic_forms(a, m));  // the same kernel on the same operands: the same bits
}

TEST(RowColumnGroups, OnlyTheFirstColumnsAsked) {
  // Columns beyond d do not split the groups.
  Eigen::MatrixXd a = Eigen::MatrixXd::Ones(4, 5);
  a(1, 4) = 0.0;
  a(2, 3) = 0.0;
  EXPECT_EQ(group_rows_by_columns(a, 3).rows.size(), 1u);
  EXPECT_EQ(group_rows_by_columns(a, 5).rows.size(), 3u);
}

}  // namespace
}  // namespace insmc::runs
