#pragma once
/// Linear maps from the uncertainty vector to scalars (one row) and the
/// helpers that build them. Every model quantity that is linear in the
/// uncertainties (misalignments, K and U matrices, position errors) is
/// represented as such a map, so that one sample is a matrix product.
#include "lib/uncertainty/uncertainty_vector.h"

namespace insmc {

using RowMap = Eigen::Matrix<double, 1, uncertainty_slot::kDim>;

/// The map picking `scale` times the uncertainty in slot `index`.
inline RowMap pick(int index, double scale = 1.0) {
  RowMap r = RowMap::Zero();
  r[index] = scale;
  return r;
}

/// Stacks three rows into a 3×kDim map.
inline Sensitivity3 stack(const RowMap& x, const RowMap& y, const RowMap& z) {
  Sensitivity3 m;
  m.row(0) = x;
  m.row(1) = y;
  m.row(2) = z;
  return m;
}

}  // namespace insmc
