#pragma once
/// The residual uncertainty matrices of compensation scheme 5.4 (alignment
/// data only, §5.4.1–5.4.3) as linear maps, for Table 5.2:
///   U'2  (5.20)   after the accelerometer outputs (5.19) are fed to point 2;
///   U'3  (5.21), (5.17a)  with the drift estimates (5.15), (5.15c) at point 4;
///   U'4  (5.17b), U'5 (5.17c): (3.29d, e) with ω_do replaced by (5.16a).
/// The maps act on the catalogue uncertainties plus the quantities the
/// report adds in chapters 4–5 that are not sampled by insmc: the analysis'
/// error in g, δg (4.1a), and the estimate errors E4 (5.15a), E5 (5.19).
/// Valid under the assumptions of (3.29): t ≤ 1.5 h, products of
/// uncertainties dropped, the alignment in steady state.
#include <Eigen/Core>

#include "lib/common/model_options.h"
#include "lib/common/system.h"
#include "lib/uncertainty/row_map.h"

namespace insmc::tables {

/// Columns of an extended map: 0 … uncertainty_slot::kDim − 1 are the catalogue slots.
namespace map_column {
inline constexpr int kGravityError = uncertainty_slot::kDim;  ///< δg [m/s²], error in the estimated g (4.1a), (4.3a), (5.19)
inline constexpr int kEps4 = uncertainty_slot::kDim + 1;      ///< ε4x,y,z, dimensionless: drift-estimate errors / ω_ie (5.15a) (3)
inline constexpr int kEps5 = uncertainty_slot::kDim + 4;      ///< ε5x,y,z, dimensionless: accelerometer-output errors / g (5.19) (3)
inline constexpr int kDim = uncertainty_slot::kDim + 7;
}  // namespace map_column

using ExtendedMap = Eigen::Matrix<double, 3, map_column::kDim>;

/// A catalogue map with zero columns for the extra quantities.
ExtendedMap extend(const Sensitivity3& m);

/// U'2..U'5 of scheme 5.4, dimensionless, a' frame.
struct ResidualMatrices {
  ExtendedMap u2, u3, u4, u5;
};

/// Scheme 5.4 residuals for `system`. U'3, U'4, U'5 are the forms before the
/// report's last simplification ((5.21) first line, (5.17b) first line,
/// (5.17c) first line): (3.29c–e) with the misalignment C, C' of (2.11),
/// (2.16), (2.18b) and the residual drift ω'_do of (5.16a); the printed
/// simplified forms (5.17a–c) drop η, ξ, ψ_ω and C-terms below 10⁻⁴ and agree
/// on every uncertainty Table 5.2 lists. `corrected_muy` multiplies the
/// g·MUY terms by cos L_0 (tables/notes/errata.md#3-13).
ResidualMatrices alignment_data_residuals(System system, const ModelOptions& options,
                                          bool corrected_muy);

}  // namespace insmc::tables
