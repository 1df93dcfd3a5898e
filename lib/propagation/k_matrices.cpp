#include "lib/propagation/k_matrices.h"

#include <cmath>

#include "lib/alignment/alignment.h"

namespace insmc {
namespace {

KMatrices build(System system, const ModelOptions& o, double muy_factor) {
  const double g = o.gravity_mps2, w = o.earth_rate_radps, r0 = o.radius_m;
  const double s = std::sin(o.latitude_rad), c = std::cos(o.latitude_rad);
  const PaperAlignmentTerms t = paper_alignment_terms(system, o);
  auto x = [](int i, double k = 1.0) { return pick(i, k); };
  const RowMap dfx = x(uncertainty_slot::kAccelBias + 0, 1 / g), dfy = x(uncertainty_slot::kAccelBias + 1, 1 / g),
               dfz = x(uncertainty_slot::kAccelBias + 2, 1 / g);
  const RowMap pfx = x(uncertainty_slot::kBiasChangeConst + 0, 1 / g) + x(uncertainty_slot::kBiasChangeAlign + 0, 1 / g);
  const RowMap pfy = x(uncertainty_slot::kBiasChangeConst + 1, 1 / g) + x(uncertainty_slot::kBiasChangeAlign + 1, 1 / g);
  const RowMap ax = x(uncertainty_slot::kAccelScale + 0), ay = x(uncertainty_slot::kAccelScale + 1), az = x(uncertainty_slot::kAccelScale + 2);
  const RowMap xi = x(uncertainty_slot::kDeflection + 0), eta = x(uncertainty_slot::kDeflection + 1);
  const RowMap dL = x(uncertainty_slot::kLatitudeError), dh3 = x(uncertainty_slot::kAltitudeError, 3.0 / r0);
  const RowMap wdx = x(uncertainty_slot::kGyroDrift + 0, 1 / w), wdy = x(uncertainty_slot::kGyroDrift + 1, 1 / w),
               wdz = x(uncertainty_slot::kGyroDrift + 2, 1 / w);
  const RowMap wmx = x(uncertainty_slot::kGyroMuDrift + 0, 1 / w), wmy = x(uncertainty_slot::kGyroMuDrift + 1, 1 / w),
               wmz = x(uncertainty_slot::kGyroMuDrift + 2, 1 / w);
  // g·MUY_k / ω_ie; muy_factor = 1 as printed, cos L_0 corrected.
  const RowMap my_x = x(uncertainty_slot::kGyroMuyDrift + 0, muy_factor / w),
               my_y = x(uncertainty_slot::kGyroMuyDrift + 1, muy_factor / w),
               my_z = x(uncertainty_slot::kGyroMuyDrift + 2, muy_factor / w);
  const RowMap pwx = t.psi_omega.row(0), pwy = t.psi_omega.row(1), pwz = t.psi_omega.row(2);
  const RowMap zx = t.zeta.row(0), zy = t.zeta.row(1), zpz = t.zeta_prime_z;
  const RowMap pfz = t.psi_fz, paz = t.psi_alpha_z;
  const RowMap zero = RowMap::Zero();

  KMatrices k;
  // (3.25a), transcription fix ∂f_z → δf_z.
  k[0] = stack(pfx + pwy + zy + dL, pfy - pwx - zx, dfz - az - dh3);
  // (3.25b)
  k[1] = stack(wdy, -wdx, zero);
  // (3.25c), transcription fix −ζ'_x → −ζ_x.
  k[2] = stack(c * pfz + s * eta + c * paz + c * pwz + c * zpz,  //
               c * ay + s * xi + c * dh3,                       //
               -c * dfy - c * pwx - c * zx);
  // (3.25d), transcription fix (g/ω_ie)[MUY_y; −MUY_x; 0].
  k[3] = stack(c * c * dfx + s * c * ax + (1 - 2 * c * c) * xi - c * c * pwy - c * c * zy +
                   s * c * dh3 - c * c * dL + my_y,
               c * c * dfy - s * c * pfz - (1 - c * c) * eta - s * c * paz + c * c * pwx -
                   s * c * pwz + c * c * zx - s * c * zpz - my_x,
               -s * c * dfx + c * c * az + 2 * s * c * xi + s * c * pwy + s * c * zy + c * c * dh3 +
                   s * c * dL);
  // (3.25e)–(3.25k)
  k[4] = c * stack(wdz, zero, -wdx);
  k[5] = c * stack(-c * wdy, c * wdx - s * wdz, s * wdy);
  k[6] = stack(wmy, -wmx, zero);
  k[7] = c * stack(my_z, zero, -my_x);
  k[8] = c * stack(-c * my_y, c * my_x - s * my_z, s * my_y);
  k[9] = c * stack(wmz, zero, -wmx);
  k[10] = c * stack(-c * wmy, c * wmx - s * wmz, s * wmy);
  return k;
}

}  // namespace

KMatrices paper_k_matrices(System system, const ModelOptions& o) { return build(system, o, 1.0); }

KMatrices corrected_k_matrices(System system, const ModelOptions& o) {
  return build(system, o, std::cos(o.latitude_rad));
}

std::array<double, 11> k_time_functions(double p) {
  const double s = std::sin(p), c1 = 1.0 - std::cos(p), v = p - s;
  return {1.0, p, s, c1, p * s, p * c1, v, s * c1, c1 * c1, s * v, c1 * v};
}

}  // namespace insmc
