#pragma once
/// The `paper` fidelity level: the report's short-run closed form (3.29) with
/// the printed coefficient matrices δV(0) (3.23), δr(0) (3.22), U2..U5
/// (3.29b–e), transcription slips fixed, errors of the original kept (they
/// are what `paper` reproduces; `linear` corrects them).
#include "lib/common/model_options.h"
#include "lib/common/system.h"
#include "lib/propagation/k_matrices.h"
#include "lib/uncertainty/row_map.h"

namespace insmc {

/// The coefficient maps of (3.29) for one system.
struct ShortRunMatrices {
  Sensitivity3 initial_position_m;  ///< δr(0)^{a'} = (r0 δL_0, 0, −δh) (3.22) [m]
  Sensitivity3 initial_velocity_mps;  ///< δV(0)^{a'} (3.23) as printed [m/s]
  Sensitivity3 u2, u3, u4, u5;      ///< (3.29b–e) as printed, dimensionless
};

ShortRunMatrices paper_short_run_matrices(System system, const ModelOptions& options);

/// S(t), the position error δr^{a'}(t) per unit of each uncertainty by (3.29). [m]
Sensitivity3 short_run_position_map(const ShortRunMatrices& m, double t_s,
                                    const ModelOptions& options);

/// Position error by (3.27) or (3.28) from K matrices. [m]
Sensitivity3 closed_form_position_map(const KMatrices& k, const Sensitivity3& initial_position_m,
                                      const Sensitivity3& initial_velocity_mps, double t_s,
                                      const ModelOptions& options, bool full_3_27);

}  // namespace insmc
