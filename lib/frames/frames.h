#pragma once
/// The report's frames (List of Symbols, §3.1):
///   a   actual instrument (platform) frame;
///   a'  ideal instrument frame: x north, y east, z down at t = 0, then fixed
///       in inertial space (space-stabilized platform);
///   a0  actual instrument frame at t = 0;
///   n   geographic frame (north, east, down), turning with the earth;
///   i   earth-centred inertial frame, z along the earth axis, x through the
///       vehicle's meridian at t = 0 (λ_0 = 0).
/// A direction-cosine matrix is C_<to>_<from>, so C_ap_n * v_n is in a'.
#include <Eigen/Core>
#include <Eigen/Geometry>  // cross products
#include <cmath>

namespace insmc {

using Mat3 = Eigen::Matrix3d;
using Vec3 = Eigen::Vector3d;

/// The report's skew form for small rotation angles c = (c_x, c_y, c_z):
/// [[0, c_z, −c_y], [−c_z, 0, c_x], [c_y, −c_x, 0]] = −[c×], as in (2.4),
/// (2.18) and (3.7): I + skew(c) maps the unrotated frame into the frame
/// turned by +c.
inline Mat3 paper_skew(const Vec3& c) {
  Mat3 m;
  m << 0.0, c.z(), -c.y(), -c.z(), 0.0, c.x(), c.y(), -c.x(), 0.0;
  return m;
}

/// B(t) of (3.5): C_n^{a'}(t) = I + B(t) for the vehicle at rest at
/// latitude L_0, the earth having turned ω_ie t since switch-over.
inline Mat3 earth_turn_B(double latitude_rad, double earth_turn_rad) {
  const double s = std::sin(earth_turn_rad), c1 = 1.0 - std::cos(earth_turn_rad);
  const double sL = std::sin(latitude_rad), cL = std::cos(latitude_rad);
  Mat3 b;
  b << c1 * sL * sL, -s * sL, c1 * sL * cL,  //
      s * sL, c1, s * cL,                    //
      c1 * sL * cL, -s * cL, c1 * cL * cL;
  return -b;
}

/// C_n^{a'}(t) = C_i^{a'} C_n^i(t) (3.1)–(3.4).
inline Mat3 C_ap_n(double latitude_rad, double earth_turn_rad) {
  return Mat3::Identity() + earth_turn_B(latitude_rad, earth_turn_rad);
}

/// C_i^{a'} of (3.2) (λ_0 = 0).
inline Mat3 C_ap_i(double latitude_rad) {
  const double sL = std::sin(latitude_rad), cL = std::cos(latitude_rad);
  Mat3 m;
  m << -sL, 0.0, cL, 0.0, 1.0, 0.0, -cL, 0.0, -sL;
  return m;
}

/// C_n^i(t) of (3.3) at latitude L and longitude λ (in i) = ω_ie t.
inline Mat3 C_i_n(double latitude_rad, double longitude_rad) {
  const double sL = std::sin(latitude_rad), cL = std::cos(latitude_rad);
  const double sl = std::sin(longitude_rad), cl = std::cos(longitude_rad);
  Mat3 m;
  m << -sL * cl, -sl, -cL * cl,  //
      -sL * sl, cl, -cL * sl,    //
      cL, 0.0, -sL;
  return m;
}

}  // namespace insmc
