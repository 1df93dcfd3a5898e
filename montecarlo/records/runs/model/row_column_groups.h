#pragma once
/// The rows of a run model grouped by the causes they see. A row's
/// quadratic form a_i M a_iᵀ (quadratic_forms.h) needs only the columns
/// where a_i is nonzero, and a layout's rows fall in a few such patterns: an
/// f row sees neither the pulse counting's r-row columns nor the initial
/// position, an r row of one axis not the other axes' accelerometer terms.
/// Half the columns per row is a quarter of the forms' work.
#include <Eigen/Core>
#include <cstddef>
#include <span>
#include <vector>

namespace insmc::runs {

struct RowColumnGroups {
  std::vector<std::vector<Eigen::Index>> rows;     ///< per group, ascending
  std::vector<std::vector<Eigen::Index>> columns;  ///< per group, the columns its rows see, ascending
};

/// The rows of `a` grouped by which of its first `d` columns are nonzero:
/// each group's columns hold every nonzero of its rows' among those. Rows of
/// one pattern share a group; patterns are joined where that costs the forms
/// less than apart (a group's own cost, its block of M gathered and its
/// blocks' tails, against the columns its rows take in vain): a random
/// process' knots give a row of every time its own pattern (the knots up to
/// it), hundreds of patterns that differ in a few late columns.
RowColumnGroups group_rows_by_columns(const Eigen::MatrixXd& a, Eigen::Index d);

/// The forms' cost of `groups` in multiply-adds and rows' worth of each
/// group's own cost: Σ (rows + kGroupOverheadRows) × columns².
inline constexpr double kGroupOverheadRows = 8.0;
double grouped_forms_cost(const RowColumnGroups& groups);

/// Each group's rows over its columns (rows × columns), the operands of
/// grouped_row_quadratic_forms: group row r is row source_rows[r] of `a`
/// (row r when source_rows is empty), column c scaled by column_scale[c]
/// (not when it is empty). One pass, whatever the rows are cut from.
std::vector<Eigen::MatrixXd> group_blocks(const Eigen::MatrixXd& a, const RowColumnGroups& groups,
                                          std::span<const Eigen::Index> source_rows,
                                          const Eigen::VectorXd& column_scale);

/// q[i] = a_i M a_iᵀ for the `rows` rows and M symmetric (its lower triangle
/// read), each group's rows over its own columns (`blocks`, group_blocks):
/// the same forms as over every column, bit for bit (the terms left out are
/// exact zeros, and the sums run in the columns' order either way).
Eigen::VectorXd grouped_row_quadratic_forms(const std::vector<Eigen::MatrixXd>& blocks, const Eigen::MatrixXd& m,
                                            const RowColumnGroups& groups, Eigen::Index rows);

}  // namespace insmc::runs
