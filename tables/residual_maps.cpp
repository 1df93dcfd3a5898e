#include "tables/residual_maps.h"

#include <cmath>

#include "lib/alignment/alignment.h"

namespace insmc::tables {
namespace {

using ExtendedRow = Eigen::Matrix<double, 1, map_column::kDim>;

ExtendedRow extend_row(const RowMap& r) {
  ExtendedRow e = ExtendedRow::Zero();
  e.head<uncertainty_slot::kDim>() = r;
  return e;
}

ExtendedRow pick_x(int column, double scale = 1.0) {
  ExtendedRow e = ExtendedRow::Zero();
  e[column] = scale;
  return e;
}

ExtendedMap stack_x(const ExtendedRow& x, const ExtendedRow& y, const ExtendedRow& z) {
  ExtendedMap m;
  m.row(0) = x;
  m.row(1) = y;
  m.row(2) = z;
  return m;
}

}  // namespace

ExtendedMap extend(const Sensitivity3& m) {
  ExtendedMap e = ExtendedMap::Zero();
  e.leftCols<uncertainty_slot::kDim>() = m;
  return e;
}

ResidualMatrices alignment_data_residuals(System system, const ModelOptions& o, bool corrected_muy) {
  const double g = o.gravity_mps2, w = o.earth_rate_radps, r0 = o.radius_m;
  const double sL = std::sin(o.latitude_rad), cL = std::cos(o.latitude_rad);
  const double muy = corrected_muy ? cL : 1.0;
  const bool sys1 = system == System::kTheodolite;
  const PaperAlignmentTerms terms = paper_alignment_terms(system, o);
  // Steady-state misalignment C (2.11), (2.16) and C' at switch-over (2.18b).
  const ExtendedMap c = extend(simplified_steady_state_misalignment(system, o));
  const ExtendedMap cp = extend(paper_switchover_misalignment(system, o));
  const ExtendedRow psi_wz = extend_row(terms.psi_omega.row(2));
  const ExtendedRow eps4x = pick_x(map_column::kEps4 + 0), eps4y = pick_x(map_column::kEps4 + 1),
                    eps4z = pick_x(map_column::kEps4 + 2);

  // (5.16a): residual drift after the torquer compensation (5.15)/(5.15c), per ω_ie.
  //   ω'_dox/ω_ie = C_y sin L0 + ε4x,  ω'_doz/ω_ie = C_y cos L0 + ε4z,
  //   ω'_doy/ω_ie = −C_z cos L0 − C_x sin L0 + ε4y (1);  ω_doy/ω_ie (2), not estimated.
  const ExtendedRow wx = sL * c.row(1) + eps4x;
  const ExtendedRow wz = cL * c.row(1) + eps4z;
  const ExtendedRow wy = sys1 ? ExtendedRow(-cL * c.row(2) - sL * c.row(0) + eps4y)
                              : pick_x(uncertainty_slot::kGyroDrift + 1, 1.0 / w);
  const ExtendedRow muy_x = pick_x(uncertainty_slot::kGyroMuyDrift + 0, muy / w),
                    muy_y = pick_x(uncertainty_slot::kGyroMuyDrift + 1, muy / w),
                    muy_z = pick_x(uncertainty_slot::kGyroMuyDrift + 2, muy / w);

  ResidualMatrices r;
  // (5.20): U'2 = [∂f_x/g + Δζ_y + ε5x; ∂f_y/g − Δζ_x + ε5y; δg/g − 2δh/r0 + ε5z], with
  // Δζ = ζ − ζ' = ζ_r (ζ' of (5.19) holds only ζ_c) and the transcription fix δg → δg/g.
  const ExtendedRow pfx = pick_x(uncertainty_slot::kBiasChangeConst + 0, 1 / g) + pick_x(uncertainty_slot::kBiasChangeAlign + 0, 1 / g);
  const ExtendedRow pfy = pick_x(uncertainty_slot::kBiasChangeConst + 1, 1 / g) + pick_x(uncertainty_slot::kBiasChangeAlign + 1, 1 / g);
  r.u2 = stack_x(pfx + pick_x(uncertainty_slot::kMisalignAlign + 1) + pick_x(map_column::kEps5 + 0),
                 pfy - pick_x(uncertainty_slot::kMisalignAlign + 0) + pick_x(map_column::kEps5 + 1),
                 pick_x(map_column::kGravityError, 1 / g) + pick_x(uncertainty_slot::kAltitudeError, -2 / r0) +
                     pick_x(map_column::kEps5 + 2));
  // (5.21): U'3 = [C'_z; 0; −C'_x] cos L0 + [ω'_doy; −ω'_dox; 0]/ω_ie.
  r.u3 = stack_x(cL * cp.row(2) + wy, -wx, -cL * cp.row(0));
  // (3.29d) with ω'_do: U'4 = [2 cos L0 ω'_doz/ω_ie + g·MUY_y/ω_ie;
  //   −ψ_ωz sin L0 cos L0 − g·MUY_x/ω_ie; −2 cos L0 ω'_dox/ω_ie]   (5.17b first line).
  r.u4 = stack_x(2 * cL * wz + muy_y, -sL * cL * psi_wz - muy_x, -2 * cL * wx);
  // (3.29e) with ω'_do: U'5 = 3 cos L0 [−ω'_doy cos L0/ω_ie − ψ_ωz/3 + g·MUY_z/ω_ie;
  //   (ω'_dox cos L0 − ω'_doz sin L0)/ω_ie; ω'_doy sin L0/ω_ie − g·MUY_x/ω_ie]   (5.17c first line;
  //   for system 2 its ω_doy terms are the printed (1/ω_ie)[−ω_doy(3cos²L0 − 1); 0; 3ω_doy sin L0 cos L0]).
  r.u5 = (3 * cL) * stack_x(-cL * wy - psi_wz / 3.0 + muy_z, cL * wx - sL * wz, sL * wy - muy_x);
  return r;
}

}  // namespace insmc::tables
