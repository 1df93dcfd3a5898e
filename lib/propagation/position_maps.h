#pragma once
/// S(t): the uncompensated position error δr^{a'}(t) per unit of each
/// uncertainty at the chosen fidelity (paper: (3.29) as printed; linear:
/// the corrected linear model integrated), and its north–east components in
/// the local-level frame at time t.
#include <vector>

#include "lib/common/model_options.h"
#include "lib/common/system.h"
#include "lib/uncertainty/row_map.h"

namespace insmc {

/// S(t) at each of `times_s` (ascending, ≥ 0) [m per SI unit].
std::vector<Sensitivity3> position_maps(System system, Fidelity fidelity, const ModelOptions& options,
                                        const std::vector<double>& times_s);

/// Rows (north, east) of C_{a'}^{n}(t) = (I + B(t))ᵀ: the local-level
/// horizontal components of an a' vector at time t (`horizontal` outputs are
/// the north–east magnitude in the local-level frame).
Eigen::Matrix<double, 2, 3> local_level_horizontal(double t_s, const ModelOptions& options);

}  // namespace insmc
