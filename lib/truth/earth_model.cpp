#include "lib/truth/earth_model.h"

#include <cmath>
#include <numbers>

#include "lib/common/assert.h"

namespace insmc {

Vec3 GravityField::gravitation(const Vec3& r) const {
  const double r2 = r.squaredNorm();
  const double rn = std::sqrt(r2);
  const double scale = -mu_m3ps2 / (r2 * rn);
  if (j2 == 0.0) return scale * r;
  // a_xy = −μ x/r³ [1 + k (1 − 5 z²/r²)], a_z = −μ z/r³ [1 + k (3 − 5 z²/r²)],
  // k = (3/2) J2 (a/r)² (the standard J2 zonal term).
  const double k = 1.5 * j2 * reference_radius_m * reference_radius_m / r2;
  const double z2 = r.z() * r.z() / r2;
  const double horizontal = 1.0 + k * (1.0 - 5.0 * z2);
  const double axial = 1.0 + k * (3.0 - 5.0 * z2);
  return Vec3(scale * horizontal * r.x(), scale * horizontal * r.y(), scale * axial * r.z());
}

GravityField model_gravity_field(double gravity_mps2, double radius_m, double j2) {
  INSMC_ASSERT(gravity_mps2 > 0 && radius_m > 0, "g = {}, r0 = {}", gravity_mps2, radius_m);
  return GravityField{gravity_mps2 * radius_m * radius_m, j2, radius_m};
}

double plumb_latitude(const GravityField& field, double w, double R, double phi) {
  const Vec3 r(R * std::cos(phi), 0.0, R * std::sin(phi));
  const Vec3 gravity = field.gravitation(r) + w * w * Vec3(r.x(), r.y(), 0.0);
  return std::atan2(-gravity.z(), -gravity.x());
}

double geocentric_latitude_for_plumb(const GravityField& field, double w, double R,
                                     double L) {
  // |L| up to π: near a pole, the computer's latitude L0 + δL (a latitude
  // error) can lie across it; cos L < 0 is then the point across the pole,
  // which these formulas describe as well.
  INSMC_ASSERT(std::abs(L) < std::numbers::pi, "plumb latitude {} rad", L);
  // dL/dφ = 1 + O(ω²R/g, J2): the plain fixed-point iteration contracts by
  // ~0.004 per step.
  double phi = L;
  for (int i = 0; i < 60; ++i) {
    const double step = L - plumb_latitude(field, w, R, phi);
    phi += step;
    if (std::abs(step) < 1e-17) break;
  }
  return phi;
}

Vec3 position_for_plumb_latitude(const GravityField& field, double w, double R, double L) {
  const double phi = geocentric_latitude_for_plumb(field, w, R, L);
  return Vec3(R * std::cos(phi), 0.0, R * std::sin(phi));
}

}  // namespace insmc
