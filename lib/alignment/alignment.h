#pragma once
/// Platform alignment (chapter 2) for system 1 (leveling loops + theodolite
/// azimuth, §2.1) and system 2 (leveling loops + gyrocompassing, §2.2), as
/// linear maps from the uncertainty vector. The platform stays level and
/// aligned to north up to the small angles C = (C_x, C_y, C_z) of (2.4).
///
/// Two forms:
///  * the report's simplified steady state (2.11), (2.16) and the
///    misalignment at switch-over (2.17), (2.18c) — the `paper` level;
///  * the full 3×3 steady-state equations (2.10), (2.14) with finite loop
///    gains, and (2.18a) C' = C + ζ_r read literally (ζ_r is the step at
///    switch-over) — the `linear` level.
#include "lib/common/model_options.h"
#include "lib/common/system.h"
#include "lib/uncertainty/row_map.h"

namespace insmc {

/// The report's named pieces of the misalignment (2.17a–d), simplified
/// steady state, as maps of the uncertainties. Angles in rad.
struct PaperAlignmentTerms {
  RowMap psi_fz;        ///< ψ_fz: (u)ψ (sys 1); −δf_y/g tan L_0 (sys 2) (2.17a, transcription fix)
  RowMap psi_alpha_z;   ///< ψ_αz: 0 (sys 1); −η tan L_0 (sys 2) (2.17b)
  Sensitivity3 psi_omega;  ///< ψ_ω: ω_do/F(0), ω_doz/F_T(0) (sys 1); (0, 0, −ω_doy/(ω_ie cos L_0)) (sys 2) (2.17c)
  Sensitivity3 zeta;    ///< ζ = ζ_c + ζ_r (2.17d)
  RowMap zeta_prime_z;  ///< ζ'_z: ζ_z (sys 1); ζ_z − ζ_x tan L_0 (sys 2) (2.17d)
};

PaperAlignmentTerms paper_alignment_terms(System system, const ModelOptions& options);

/// C'^a, the misalignment just after switch-over, as printed in (2.18b, c)
/// (transcription fix of the z row: ω_doz/F_T(0) for system 1).
Sensitivity3 paper_switchover_misalignment(System system, const ModelOptions& options);

/// C^a, the steady-state misalignment during alignment from the full 3×3
/// equations (2.10) (sys 1) or (2.14) (sys 2), with the electronics offsets
/// V_0 expressed through ζ_c by (2.11a), (2.15a). Includes (u)ψ for system 1
/// but not the switch-over step ζ_r.
Sensitivity3 full_steady_state_misalignment(System system, const ModelOptions& options);

/// C^a from the simplified (2.11) (sys 1) or (2.16) (sys 2).
Sensitivity3 simplified_steady_state_misalignment(System system, const ModelOptions& options);

/// C'^a = C^a + ζ_r (2.18a) with C^a from the full equations: the `linear`
/// level's misalignment at switch-over.
Sensitivity3 full_switchover_misalignment(System system, const ModelOptions& options);

/// Steady-state gyro torquer command rates from the alignment electronics,
/// ω_c^a = (C_n^a − I) ω_in^n − ω_do (5.13), (5.14), for a given steady
/// state C^a map. [rad/s]
Sensitivity3 torquer_commands(const Sensitivity3& steady_state_C, const ModelOptions& options);

/// Steady-state accelerometer output errors at the end of alignment,
/// Δf_m^a = f_m^a − f̂ (5.18), (5.19), for a given steady-state C^a map, with
/// the analysis' gravity error δg set as in §4.1 (δg/g = −3 δh/r0). [m/s²]
Sensitivity3 alignment_accelerometer_outputs(const Sensitivity3& steady_state_C,
                                             const ModelOptions& options);

}  // namespace insmc
