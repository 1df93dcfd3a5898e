#pragma once
/// The truth simulator's earth: gravitation (a sphere, optionally with the J2
/// zonal term), the earth's rotation, and the site where the vehicle stands.
///
/// Frames (lib/frames/frames.h): e is the earth-fixed frame that coincides
/// with i at t = 0 (z along the earth axis, x through the site's meridian);
/// r^i(t) = R_z(ω_ie t) r^e.
///
/// Choice of the gravitational constant: μ = g r0² with g = ModelOptions::
/// gravity_mps2 and r0 = ModelOptions::radius_m, so that the Schuler frequency
/// of the navigation computer, sqrt(μ/r0³), is exactly the one the linear model
/// uses (ω_s² = g/r0, §3.2.2). The specific force at the site is then gravity
/// (gravitation plus centrifugal), |f| = g − ω_ie² r0 cos²φ + … ≈ g (1 − 0.17%)
/// at 45°: the report does not distinguish gravitation from gravity, and this
/// split puts the whole difference into the size of g-proportional terms
/// (0.17%) instead of also into the Schuler phase (which would follow from
/// choosing μ so that |f| = g).
///
/// Latitude: L0 is the latitude of the plumb line (the direction of gravity,
/// gravitation plus centrifugal, of the reference field without deflection of
/// the vertical), which the leveling loops find. The site's geocentric
/// latitude φ (≈ L0 − 0.0017 rad at 45°) follows from it.
#include "lib/frames/frames.h"

namespace insmc {

/// J2 of the earth (WGS-84 / EGM: 1.08263e-3), dimensionless.
inline constexpr double kEarthJ2 = 1.08263e-3;

/// Gravitation of a sphere plus an optional J2 term, in an earth-fixed frame
/// with z along the axis (the field is symmetric about z, so also in i).
struct GravityField {
  double mu_m3ps2 = 0.0;           ///< gravitational parameter μ [m³/s²], > 0
  double j2 = 0.0;                 ///< J2, dimensionless (0: sphere)
  double reference_radius_m = 0.0; ///< radius of the J2 expansion [m], > 0

  /// Gravitation at r (any frame with z along the earth axis) [m/s²].
  Vec3 gravitation(const Vec3& r_m) const;
};

/// The field of the model: μ = g r0², reference radius r0, the given J2.
GravityField model_gravity_field(double gravity_mps2, double radius_m, double j2);

/// Latitude of the plumb line at the meridian-plane point
/// R (cos φ, 0, sin φ): the direction of gravitation plus centrifugal
/// ω_ie² (x, y, 0) [rad].
double plumb_latitude(const GravityField& field, double earth_rate_radps, double radius_m,
                      double geocentric_latitude_rad);

/// The geocentric latitude φ at radius R whose plumb line has latitude L
/// (inverse of plumb_latitude; fixed-point iteration to round-off) [rad].
/// Precondition: |L| < 90°.
double geocentric_latitude_for_plumb(const GravityField& field, double earth_rate_radps,
                                     double radius_m, double plumb_latitude_rad);

/// Position in e of the point at radius R on the meridian λ = 0 whose plumb
/// line has latitude L [m]: how both the truth places the vehicle and the
/// navigation computer sets its initial position (3.22) from L̂0 and the
/// external altitude, each with its own field.
Vec3 position_for_plumb_latitude(const GravityField& field, double earth_rate_radps,
                                 double radius_m, double plumb_latitude_rad);

/// R_z(angle): the rotation taking e-frame vectors to i after the earth
/// has turned by `angle` (= ω_ie t) [rad].
inline Mat3 earth_rotation(double angle_rad) {
  const double c = std::cos(angle_rad), s = std::sin(angle_rad);
  Mat3 m;
  m << c, -s, 0.0, s, c, 0.0, 0.0, 0.0, 1.0;
  return m;
}

}  // namespace insmc
