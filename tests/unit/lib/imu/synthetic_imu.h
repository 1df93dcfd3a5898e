#pragma once
// A synthetic stationary IMU for the import-imu tests: the exact body-frame
// gyro and accelerometer outputs of a sensor fixed to the model earth
// (lib/truth/earth_model.h: sphere, μ = g r0²), built from the earth model and
// explicit rotation matrices, not from lib/imu/strapdown.cpp.
#include <fmt/format.h>

#include <cmath>
#include <functional>
#include <string>

#include "lib/frames/frames.h"
#include "lib/imu/imu_samples.h"
#include "lib/truth/earth_model.h"
#include "lib/units/units.h"

namespace insmc::testing {

/// Where the sensor stands and how it is turned.
struct SyntheticSite {
  double latitude_rad = 45.0 * kDegToRad;  ///< plumb-line latitude
  double altitude_m = 0.0;                 ///< above r0
  double heading_rad = 0.0;                ///< sensor x from north, toward east
  double pitch_rad = 0.0;
  double roll_rad = 0.0;
};

/// The exact outputs of a perfect sensor at the site (constant: the body is
/// fixed to the earth and the specific force is fixed in n).
struct PerfectOutputs {
  Vec3 gyro_b_radps;     ///< ω_ib^b = C_b^n ω_ie^n
  Vec3 accel_b_mps2;     ///< f^b = C_b^n f^n
  double gravity_mps2;   ///< |f|
};

/// C_n_b = R_z(ψ) R_y(θ) R_x(φ), written out element by element.
inline Mat3 euler_321(double roll, double pitch, double heading) {
  const double cf = std::cos(roll), sf = std::sin(roll), ct = std::cos(pitch), st = std::sin(pitch);
  const double cp = std::cos(heading), sp = std::sin(heading);
  Mat3 rz, ry, rx;
  rz << cp, -sp, 0, sp, cp, 0, 0, 0, 1;
  ry << ct, 0, st, 0, 1, 0, -st, 0, ct;
  rx << 1, 0, 0, 0, cf, -sf, 0, sf, cf;
  return rz * ry * rx;
}

inline PerfectOutputs perfect_outputs(const SyntheticSite& s) {
  const GravityField field = model_gravity_field(kGravityMps2, kEarthRadiusM, 0.0);
  const double w = kEarthRateRadps;
  const Vec3 r_e = position_for_plumb_latitude(field, w, kEarthRadiusM + s.altitude_m, s.latitude_rad);
  // A point turning with the earth: r̈ = −ω × (ω × r) = G + f.
  const Vec3 f_e = -w * w * Vec3(r_e.x(), r_e.y(), 0.0) - field.gravitation(r_e);
  const Mat3 C_b_e = euler_321(s.roll_rad, s.pitch_rad, s.heading_rad).transpose() *
                     C_i_n(s.latitude_rad, 0.0).transpose();
  return PerfectOutputs{C_b_e * Vec3(0.0, 0.0, w), C_b_e * f_e, f_e.norm()};
}

/// Error added to the perfect outputs at time t (file clock) [SI].
using SampleError = std::function<void(double t_s, Vec3& gyro_radps, Vec3& accel_mps2)>;

/// `duration_s × rate_hz` samples at t = k / rate of the perfect outputs plus `error`.
inline ImuSamples synthetic_samples(const SyntheticSite& site, double rate_hz, double duration_s,
                                    const SampleError& error = {}) {
  const PerfectOutputs p = perfect_outputs(site);
  ImuSamples s;
  s.source = "synthetic";
  const long n = std::lround(duration_s * rate_hz);
  for (long k = 0; k < n; ++k) {
    const double t = static_cast<double>(k) / rate_hz;
    Vec3 gyro = p.gyro_b_radps, accel = p.accel_b_mps2;
    if (error) error(t, gyro, accel);
    s.t_s.push_back(t);
    s.gyro_b_radps.push_back(gyro);
    s.accel_b_mps2.push_back(accel);
  }
  return s;
}

/// CSV text of samples in rad/s and m/s² with the given column names (x, y,
/// z of gyro then accel), numbers in shortest round-trip form.
inline std::string samples_csv(const ImuSamples& s, const std::string& header) {
  std::string out = header + "\n";
  for (std::size_t k = 0; k < s.size(); ++k) {
    const Vec3& g = s.gyro_b_radps[k];
    const Vec3& a = s.accel_b_mps2[k];
    out += fmt::format("{},{},{},{},{},{}\n", g.x(), g.y(), g.z(), a.x(), a.y(), a.z());
  }
  return out;
}

}  // namespace insmc::testing
