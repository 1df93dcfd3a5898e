#pragma once
/// The uncertainty matrices K1..K11 of (3.25a–k) as printed (transcription
/// slips fixed, tables/notes/errata.md#transcription-slips), each a 3×kDim map in the a'
/// frame, dimensionless (the forcing of (3.25) is C_a'^i g Σ K_j f_j(t)).
///
/// Known error of the original kept here on purpose (the `paper` level):
/// the g·MUY terms of K4, K8, K9 lack a factor cos L_0, inherited from
/// (3.13) (see tables/notes/errata.md#3-13). `corrected_k_matrices` applies it.
#include <array>

#include "lib/common/model_options.h"
#include "lib/common/system.h"
#include "lib/uncertainty/row_map.h"

namespace insmc {

/// K[0] = K1 … K[10] = K11.
using KMatrices = std::array<Sensitivity3, 11>;

/// (3.25a–k) as printed, with the misalignment terms of (2.17) for `system`.
KMatrices paper_k_matrices(System system, const ModelOptions& options);

/// The same with the cos L_0 factor on every g·MUY term (errata 3.13).
KMatrices corrected_k_matrices(System system, const ModelOptions& options);

/// The eleven time functions f_j(t) of (3.25) at earth turn φ = ω_ie t:
/// 1, φ, sin φ, 1 − cos φ, φ sin φ, φ(1 − cos φ), φ − sin φ,
/// sin φ(1 − cos φ), (1 − cos φ)², sin φ(φ − sin φ), (1 − cos φ)(φ − sin φ).
std::array<double, 11> k_time_functions(double earth_turn_rad);

}  // namespace insmc
