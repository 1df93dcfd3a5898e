#pragma once
/// Some rows of a column-major vector or matrix, the step that cuts a
/// layout's model out of its lattice's.
#include <Eigen/Core>
#include <cstddef>
#include <span>

namespace insmc::runs {

/// The rows `rows` of v's first `columns` columns (all when negative); an
/// empty v (a term the model does not have) stays empty. Column by column: the matrices are column-major, and a row at a time
/// strides through all of them (it was a seventh of the diagnosis' time).
template <class Dense>
Dense rows_of(const Dense& v, std::span<const Eigen::Index> rows, Eigen::Index columns = -1) {
  if (columns < 0) columns = v.cols();
  if (v.rows() == 0) return Dense(v.leftCols(columns));
  Dense out(static_cast<Eigen::Index>(rows.size()), columns);
  for (Eigen::Index c = 0; c < columns; ++c) {
    const double* from = v.col(c).data();
    double* to = out.col(c).data();
    for (std::size_t i = 0; i < rows.size(); ++i) to[i] = from[rows[i]];
  }
  return out;
}

}  // namespace insmc::runs
