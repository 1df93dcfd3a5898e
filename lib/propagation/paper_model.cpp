#include "lib/propagation/paper_model.h"

#include <cmath>

#include "lib/alignment/alignment.h"
#include "lib/propagation/closed_form.h"

namespace insmc {

ShortRunMatrices paper_short_run_matrices(System system, const ModelOptions& o) {
  const double g = o.gravity_mps2, w = o.earth_rate_radps, r0 = o.radius_m;
  const double s = std::sin(o.latitude_rad), c = std::cos(o.latitude_rad);
  const PaperAlignmentTerms t = paper_alignment_terms(system, o);
  const RowMap zero = RowMap::Zero();
  ShortRunMatrices m;
  // (3.22): δr(0)^{a'} = (r0 δL_0, 0, −δh).
  m.initial_position_m = stack(pick(uncertainty_slot::kLatitudeError, r0), zero, pick(uncertainty_slot::kAltitudeError, -1.0));
  // (3.23) as printed: δV(0)_y = (u)V_y + 2 r0 δL_0 ω_ie sin L_0 + δh ω_ie cos L_0.
  // (The factor 2 and its sign are an error of the original, errata.md#3-23.)
  m.initial_velocity_mps =
      stack(pick(uncertainty_slot::kInitialVelocity + 0),
            pick(uncertainty_slot::kInitialVelocity + 1) + pick(uncertainty_slot::kLatitudeError, 2 * r0 * w * s) +
                pick(uncertainty_slot::kAltitudeError, w * c),
            pick(uncertainty_slot::kInitialVelocity + 2));
  const RowMap pfx = pick(uncertainty_slot::kBiasChangeConst + 0, 1 / g) + pick(uncertainty_slot::kBiasChangeAlign + 0, 1 / g);
  const RowMap pfy = pick(uncertainty_slot::kBiasChangeConst + 1, 1 / g) + pick(uncertainty_slot::kBiasChangeAlign + 1, 1 / g);
  // (3.29b): ψ_ωk(2) = 0 for k = x, y, as t.psi_omega holds.
  m.u2 = stack(pfx + t.psi_omega.row(1) + t.zeta.row(1), pfy - t.psi_omega.row(0) - t.zeta.row(0),
               pick(uncertainty_slot::kAccelBias + 2, 1 / g) - pick(uncertainty_slot::kAccelScale + 2) +
                   pick(uncertainty_slot::kAltitudeError, -2.0 / r0));
  // (3.29c), with ψ_ωz(1) ≈ 0 as printed.
  const RowMap psi_wz = system == System::kTheodolite ? zero : RowMap(t.psi_omega.row(2));
  m.u3 = stack(c * t.psi_fz + pick(uncertainty_slot::kGyroDrift + 1, 1 / w) + c * psi_wz + c * t.zeta_prime_z,
               pick(uncertainty_slot::kGyroDrift + 0, -1 / w),
               pick(uncertainty_slot::kAccelBias + 1, -c / g) - c * t.zeta.row(0));
  // (3.29d): (1/ω_ie)[2ω_doz cos L0 + gMUY_y; −ω_ie ψ_ωz sin L0 cos L0 − gMUY_x; −2ω_dox cos L0].
  m.u4 = stack(pick(uncertainty_slot::kGyroDrift + 2, 2 * c / w) + pick(uncertainty_slot::kGyroMuyDrift + 1, 1 / w),
               -s * c * psi_wz + pick(uncertainty_slot::kGyroMuyDrift + 0, -1 / w),
               pick(uncertainty_slot::kGyroDrift + 0, -2 * c / w));
  // (3.29e): (3 cos L0/ω_ie)[−ω_doy cos L0 − ω_ie ψ_ωz/3 + gMUY_z;
  //                          ω_dox cos L0 − ω_doz sin L0; ω_doy sin L0 − gMUY_x].
  m.u5 = (3 * c) * stack(pick(uncertainty_slot::kGyroDrift + 1, -c / w) - psi_wz / 3.0 +
                             pick(uncertainty_slot::kGyroMuyDrift + 2, 1 / w),
                         pick(uncertainty_slot::kGyroDrift + 0, c / w) + pick(uncertainty_slot::kGyroDrift + 2, -s / w),
                         pick(uncertainty_slot::kGyroDrift + 1, s / w) + pick(uncertainty_slot::kGyroMuyDrift + 0, -1 / w));
  return m;
}

Sensitivity3 short_run_position_map(const ShortRunMatrices& m, double t, const ModelOptions& o) {
  const ShortRunFunctions f = short_run_functions_3_29(t, o);
  const double r0 = o.radius_m;
  // (3.29)
  return f.initial_position * m.initial_position_m + f.initial_velocity_s * m.initial_velocity_mps +
         r0 * (f.u2 * m.u2 + f.u3 * m.u3 + f.u4 * m.u4 + f.u5 * m.u5);
}

Sensitivity3 closed_form_position_map(const KMatrices& k, const Sensitivity3& r0_map,
                                      const Sensitivity3& v0_map, double t, const ModelOptions& o,
                                      bool full_3_27) {
  const ClosedFormCoefficients f = full_3_27 ? closed_form_3_27(t, o) : closed_form_3_28(t, o);
  Sensitivity3 out = f.initial_position * r0_map + f.initial_velocity_s * v0_map;
  for (int j = 0; j < 11; ++j) out += o.radius_m * f.k[j] * k[j];
  return out;
}

}  // namespace insmc
