#include "lib/alignment/alignment.h"

#include <Eigen/LU>
#include <cmath>

#include "lib/frames/frames.h"

namespace insmc {
namespace {

/// 1/F for a gain ratio F/ω_ie, 0 for an infinite (integrating) gain.
double inverse_gain(double gain_ratio, double earth_rate_radps) {
  return std::isinf(gain_ratio) ? 0.0 : 1.0 / (gain_ratio * earth_rate_radps);
}

}  // namespace

PaperAlignmentTerms paper_alignment_terms(System system, const ModelOptions& o) {
  const double g = o.gravity_mps2, w = o.earth_rate_radps;
  const double tanL = std::tan(o.latitude_rad), cosL = std::cos(o.latitude_rad);
  PaperAlignmentTerms t;
  t.zeta = stack(pick(uncertainty_slot::kMisalignConst + 0) + pick(uncertainty_slot::kMisalignAlign + 0),
                 pick(uncertainty_slot::kMisalignConst + 1) + pick(uncertainty_slot::kMisalignAlign + 1),
                 pick(uncertainty_slot::kMisalignConst + 2) + pick(uncertainty_slot::kMisalignAlign + 2));
  if (system == System::kTheodolite) {
    const double f_inv = inverse_gain(o.leveling_gain_ratio, w);
    const double ft_inv = inverse_gain(o.azimuth_gain_ratio, w);
    t.psi_fz = pick(uncertainty_slot::kTheodolite);
    t.psi_alpha_z = RowMap::Zero();
    t.psi_omega = stack(pick(uncertainty_slot::kGyroDrift + 0, f_inv), pick(uncertainty_slot::kGyroDrift + 1, f_inv),
                        pick(uncertainty_slot::kGyroDrift + 2, ft_inv));
    t.zeta_prime_z = t.zeta.row(2);
  } else {
    t.psi_fz = pick(uncertainty_slot::kAccelBias + 1, -tanL / g);
    t.psi_alpha_z = pick(uncertainty_slot::kDeflection + 1, -tanL);
    t.psi_omega = stack(RowMap::Zero(), RowMap::Zero(), pick(uncertainty_slot::kGyroDrift + 1, -1.0 / (w * cosL)));
    t.zeta_prime_z = t.zeta.row(2) - tanL * t.zeta.row(0);
  }
  return t;
}

Sensitivity3 paper_switchover_misalignment(System system, const ModelOptions& o) {
  const double g = o.gravity_mps2;
  const PaperAlignmentTerms t = paper_alignment_terms(system, o);
  // (2.18b): C'_x = δf_y/g + η + ψ_ωx + ζ_x; C'_y = −(δf_x/g − ξ) + ψ_ωy + ζ_y;
  //          C'_z = ψ_fz + ψ_αz + ψ_ωz + ζ'_z.
  const RowMap cx = pick(uncertainty_slot::kAccelBias + 1, 1.0 / g) + pick(uncertainty_slot::kDeflection + 1) +
                    t.psi_omega.row(0) + t.zeta.row(0);
  const RowMap cy = pick(uncertainty_slot::kAccelBias + 0, -1.0 / g) + pick(uncertainty_slot::kDeflection + 0) +
                    t.psi_omega.row(1) + t.zeta.row(1);
  const RowMap cz = t.psi_fz + t.psi_alpha_z + t.psi_omega.row(2) + t.zeta_prime_z;
  return stack(cx, cy, cz);
}

Sensitivity3 full_steady_state_misalignment(System system, const ModelOptions& o) {
  const double g = o.gravity_mps2, w = o.earth_rate_radps;
  const double sL = std::sin(o.latitude_rad), cL = std::cos(o.latitude_rad);
  // Each row of (2.10)/(2.14) divided by its loop gain, so that an infinite
  // (integrating) gain enters as 1/F = 0.
  Mat3 a;
  Sensitivity3 rhs;
  const RowMap level_x = pick(uncertainty_slot::kAccelBias + 1, 1.0 / g) + pick(uncertainty_slot::kDeflection + 1) +
                         pick(uncertainty_slot::kMisalignConst + 0);  // δf_y/g + η + V01/g
  const RowMap level_y = pick(uncertainty_slot::kAccelBias + 0, -1.0 / g) + pick(uncertainty_slot::kDeflection + 0) +
                         pick(uncertainty_slot::kMisalignConst + 1);  // −(δf_x/g − ξ + V02/g)
  if (system == System::kTheodolite) {
    const double f = inverse_gain(o.leveling_gain_ratio, w);
    const double ft = inverse_gain(o.azimuth_gain_ratio, w);
    a << 1.0, w * sL * f, 0.0,  //
        -w * sL * f, 1.0, -w * cL * f,  //
        0.0, w * cL * ft, 1.0;
    rhs.row(0) = level_x + pick(uncertainty_slot::kGyroDrift + 0, f);
    rhs.row(1) = level_y + pick(uncertainty_slot::kGyroDrift + 1, f);
    rhs.row(2) = pick(uncertainty_slot::kTheodolite) + pick(uncertainty_slot::kMisalignConst + 2) + pick(uncertainty_slot::kGyroDrift + 2, ft);
  } else {
    // F_1, F_3 proportional-plus-integral (1/F = 0), F_2 low-pass (finite).
    const double f2 = inverse_gain(o.gyrocompass_f2_ratio, w);
    a << 1.0, 0.0, 0.0,  //
        -w * sL * f2, 1.0, -w * cL * f2,  //
        0.0, 1.0, 0.0;
    rhs.row(0) = level_x;
    // Row 2 of (2.14) with V02/g = −ζ_cy + ω_ie cos L_0 ζ_cz / F_2(0) (2.15a).
    rhs.row(1) = level_y - pick(uncertainty_slot::kMisalignConst + 2, w * cL * f2) + pick(uncertainty_slot::kGyroDrift + 1, f2);
    // Row 3 of (2.14) with V03/g = −ζ_cy.
    rhs.row(2) = level_y;
  }
  return a.inverse() * rhs;
}

Sensitivity3 simplified_steady_state_misalignment(System system, const ModelOptions& o) {
  Sensitivity3 c = paper_switchover_misalignment(system, o);
  // Remove the switch-over step: (2.11)/(2.16) hold ζ_c only (in the paper's
  // convention ζ_r enters C' through the same terms as ζ_c, (2.17d)).
  for (int k = 0; k < 3; ++k) c.col(uncertainty_slot::kMisalignAlign + k).setZero();
  return c;
}

Sensitivity3 full_switchover_misalignment(System system, const ModelOptions& o) {
  Sensitivity3 c = full_steady_state_misalignment(system, o);
  for (int k = 0; k < 3; ++k) c(k, uncertainty_slot::kMisalignAlign + k) += 1.0;  // (2.18a)
  return c;
}

Sensitivity3 torquer_commands(const Sensitivity3& C, const ModelOptions& o) {
  const double w = o.earth_rate_radps;
  const double sL = std::sin(o.latitude_rad), cL = std::cos(o.latitude_rad);
  // (5.14): ω_c = ω_ie [C_y sin L0; −C_z cos L0 − C_x sin L0; C_y cos L0] − ω_do.
  return stack(w * sL * C.row(1) - pick(uncertainty_slot::kGyroDrift + 0),
               -w * cL * C.row(2) - w * sL * C.row(0) - pick(uncertainty_slot::kGyroDrift + 1),
               w * cL * C.row(1) - pick(uncertainty_slot::kGyroDrift + 2));
}

Sensitivity3 alignment_accelerometer_outputs(const Sensitivity3& C, const ModelOptions& o) {
  const double g = o.gravity_mps2;
  // f_m = (I + A)(I + ψ_C) f^n + δf, f^n = −g_e − α (2.8), less the estimate
  // f̂ = −g_e − δg_e (4.1a); products of uncertainties dropped (5.18).
  // x: g C_y − ξ g + δf_x;  y: −g C_x + η g + δf_y;  z: δf_z − g a_z + δg.
  return stack(g * C.row(1) - pick(uncertainty_slot::kDeflection + 0, g) + pick(uncertainty_slot::kAccelBias + 0),
               -g * C.row(0) + pick(uncertainty_slot::kDeflection + 1, g) + pick(uncertainty_slot::kAccelBias + 1),
               pick(uncertainty_slot::kAccelBias + 2) - pick(uncertainty_slot::kAccelScale + 2, g) +
                   pick(uncertainty_slot::kAltitudeError, -3.0 * g / o.radius_m));
}

}  // namespace insmc
