// The rows grouped by the causes they see: each group's forms over its own
// columns against the forms over every column.
#include "montecarlo/records/runs/model/row_column_groups.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
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

/// Every row in one group, and every column where a row is nonzero among
/// its group's columns.
void expect_groups_cover(const RowColumnGroups& g, const Eigen::MatrixXd& a, Eigen::Index d) {
  std::vector<int> seen(static_cast<std::size_t>(a.rows()), 0);
  for (std::size_t k = 0; k < g.rows.size(); ++k)
    for (Eigen::Index i : g.rows[k]) {
      ++seen[static_cast<std::size_t>(i)];
      for (Eigen::Index c = 0; c < d; ++c) {
        if (a(i, c) == 0.0) continue;
        EXPECT_NE(std::find(g.columns[k].begin(), g.columns[k].end(), c), g.columns[k].end())
            << "row " << i << " column " << c;
      }
    }
  for (Eigen::Index i = 0; i < a.rows(); ++i) EXPECT_EQ(seen[static_cast<std::size_t>(i)], 1) << "row " << i;
}

TEST(RowColumnGroups, EachGroupsFormsOverItsColumnsAreTheFormsOverEveryColumn) {
  constexpr Eigen::Index d = 40, rows = 300;
  const Eigen::MatrixXd a = patterned_rows(rows, d, 6, 7);
  const Eigen::MatrixXd m = symmetric_positive(d, 8);
  const RowColumnGroups g = group_rows_by_columns(a, d);
  EXPECT_LE(g.rows.size(), 6u);
  EXPECT_GE(g.rows.size(), 2u);  // joining everything costs more than the 6 patterns apart
  expect_groups_cover(g, a, d);
  // The terms left out are exact zeros and the sums keep the columns'
  // order: the forms are those over every column, bit for bit (pattern 0
  // sees no column: its forms are 0).
  const Eigen::VectorXd grouped = grouped_row_quadratic_forms(group_blocks(a, g, {}, {}), m, g, rows);
  EXPECT_EQ(grouped, row_quadratic_forms(a, m));
  for (Eigen::Index i = 0; i < rows; i += 6) EXPECT_EQ(grouped[i], 0.0) << "row " << i;
}

TEST(RowColumnGroups, PatternsThatDifferInLateColumnsAreJoinedWhereThatCostsLess) {
  // A random process' knots as the position rows see them: row i of two
  // kinds (10 columns of its own each) and the knots up to i / 10, 80
  // patterns of 400 rows. Each pattern its own group pays each group's own
  // cost 80 times; one group over every column pays the 40 knots on every
  // row. Joined neighbours cost less than either.
  constexpr Eigen::Index d = 60, rows = 400;
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(rows, d);
  for (Eigen::Index i = 0; i < rows; ++i) {
    for (Eigen::Index c = 0; c < 10; ++c) a(i, c + (i % 2) * 10) = 1.0 + static_cast<double>(c + i % 7);
    for (Eigen::Index k = 0; k <= i / 10; ++k) a(i, 20 + k) = 0.5 + static_cast<double>(k % 5);
  }
  const RowColumnGroups g = group_rows_by_columns(a, d);
  expect_groups_cover(g, a, d);
  RowColumnGroups each_pattern, one;
  for (Eigen::Index i = 0; i < rows; ++i) {
    std::vector<Eigen::Index> cols;
    for (Eigen::Index c = 0; c < d; ++c)
      if (a(i, c) != 0.0) cols.push_back(c);
    if (i % 10 < 2) each_pattern.rows.emplace_back(), each_pattern.columns.push_back(cols);
    each_pattern.rows[static_cast<std::size_t>(i / 10 * 2 + i % 2)].push_back(i);
  }
  ASSERT_EQ(each_pattern.rows.size(), 80u);
  one.rows.emplace_back(static_cast<std::size_t>(rows));
  std::iota(one.rows[0].begin(), one.rows[0].end(), Eigen::Index{0});
  one.columns.emplace_back(static_cast<std::size_t>(d));
  std::iota(one.columns[0].begin(), one.columns[0].end(), Eigen::Index{0});
  EXPECT_LT(grouped_forms_cost(g), grouped_forms_cost(one));
  EXPECT_LT(grouped_forms_cost(g), grouped_forms_cost(each_pattern));
  EXPECT_GT(g.rows.size(), 1u);
  EXPECT_LT(g.rows.size(), 80u);
  const Eigen::MatrixXd m = symmetric_positive(d, 9);
  EXPECT_EQ(grouped_row_quadratic_forms(group_blocks(a, g, {}, {}), m, g, rows), row_quadratic_forms(a, m));
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

TEST(RowColumnGroups, RowsOfNoCommonPatternAreOneGroupOverEveryColumn) {
  constexpr Eigen::Index d = 70;  // more than one word of the pattern
  std::mt19937_64 rng(3);
  std::bernoulli_distribution half(0.5);
  Eigen::MatrixXd a(200, d);
  for (Eigen::Index i = 0; i < a.rows(); ++i)
    for (Eigen::Index c = 0; c < d; ++c) a(i, c) = half(rng) ? 1.0 + static_cast<double>(c) : 0.0;
  // 200 patterns, any two joined see three quarters of the columns: one
  // group of every row costs least.
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
  const RowColumnGroups first_three = group_rows_by_columns(a, 3);
  ASSERT_EQ(first_three.rows.size(), 1u);
  EXPECT_EQ(first_three.columns[0], (std::vector<Eigen::Index>{0, 1, 2}));
  expect_groups_cover(group_rows_by_columns(a, 5), a, 5);
}

}  // namespace
}  // namespace insmc::runs
