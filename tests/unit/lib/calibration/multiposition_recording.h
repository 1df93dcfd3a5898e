#pragma once
// A synthetic multi-position recording with known sensor errors, written
// from the calibration model's inverse (lib/calibration/multiposition.h,
// (C.1), (C.3), (C.4)): the body rests, turns at a constant body rate about
// a random axis, rests again, and so on. The attitude is propagated exactly
// per sample (C_{k+1} = C_k exp([ω dt]×)), so a noise-free recording fits
// to rounding.
#include <map>
#include <random>
#include <string>

#include <Eigen/Geometry>

#include "lib/calibration/multiposition.h"
#include "lib/imu/imu_samples.h"
#include "lib/units/units.h"

namespace insmc::testing {

struct SensorErrors {
  Vec3 accel_bias_mps2 = Vec3::Zero();
  Mat3 accel_m = Mat3::Zero();  ///< M_a, upper triangular (C.1)
  Vec3 gyro_bias_radps = Vec3::Zero();
  Mat3 g_sensitivity = Mat3::Zero();  ///< G of (C.3) [rad/s per m/s²]
  Mat3 gyro_m = Mat3::Zero();         ///< M_g of (C.4)
  double accel_noise_mps2 = 0, gyro_noise_radps = 0;  ///< white, per sample
};

/// Errors of a MEMS unit's size, drawn from `rng`.
inline SensorErrors draw_errors(std::mt19937_64& rng) {
  std::normal_distribution<double> n(0, 1);
  SensorErrors e;
  for (int i = 0; i < 3; ++i) {
    e.accel_bias_mps2[i] = 0.05 * n(rng);
    e.accel_m(i, i) = 0.01 * n(rng);
    e.gyro_bias_radps[i] = 0.01 * n(rng);
    e.gyro_m(i, i) = 0.01 * n(rng);
    for (int j = 0; j < 3; ++j) {
      e.g_sensitivity(i, j) = 1e-4 * n(rng);
      if (j != i) e.gyro_m(i, j) = 0.005 * n(rng);
      if (j > i) e.accel_m(i, j) = 0.005 * n(rng);
    }
  }
  e.accel_noise_mps2 = 0.01;
  e.gyro_noise_radps = 0.005;
  return e;
}

/// The true value of each calibrated parameter, by its name
/// (lib/calibration/multiposition.cpp's names, SI).
inline std::map<std::string, double> truth_of(const SensorErrors& e) {
  std::map<std::string, double> t;
  const char* axis = "xyz";
  for (int i = 0; i < 3; ++i) {
    t[std::string("accel_bias_") + axis[i]] = e.accel_bias_mps2[i];
    t[std::string("accel_scale_factor_") + axis[i]] = e.accel_m(i, i);
    t[std::string("gyro_bias_") + axis[i]] = e.gyro_bias_radps[i];
    t[std::string("gyro_scale_factor_") + axis[i]] = e.gyro_m(i, i);
    for (int j = 0; j < 3; ++j) {
      t[std::string("g_sensitivity_") + axis[i] + axis[j]] = e.g_sensitivity(i, j);
      if (i != j) t[std::string("gyro_misalignment_") + axis[i] + axis[j]] = e.gyro_m(i, j);
      if (j > i) t[std::string("accel_misalignment_") + axis[i] + axis[j]] = e.accel_m(i, j);
    }
  }
  return t;
}

/// `poses` still attitudes of `still_s` after a first one of 20 s, turns of
/// 3 s between them (about random body axes, or all about `only_axis`
/// when it is not zero), at 100 Hz; gravity 9.80665 m/s² along space up.
inline ImuSamples multiposition_recording(const SensorErrors& e, int poses, double still_s, std::mt19937_64& rng,
                                          const Vec3& only_axis = Vec3::Zero()) {
  constexpr double dt = 0.01, turn_s = 3.0;
  const Vec3 f_space(0, 0, kGravityMps2);
  const Mat3 accel_inverse = (Mat3::Identity() + e.accel_m).inverse();
  const Mat3 gyro_inverse = (Mat3::Identity() + e.gyro_m).inverse();
  std::normal_distribution<double> n(0, 1);
  std::uniform_real_distribution<double> angle(60 * kDegToRad, 170 * kDegToRad);
  // Three draws in this order (the order of a constructor's arguments is
  // unspecified: g++ and clang would draw different recordings).
  const auto draw3 = [&] {
    const double x = n(rng), y = n(rng), z = n(rng);
    return Vec3(x, y, z);
  };
  ImuSamples s;
  s.source = "synthetic";
  Mat3 c = Mat3::Identity();  // body to space
  const auto add = [&](const Vec3& w_body) {
    const Vec3 f = c.transpose() * f_space;
    s.t_s.push_back(dt * static_cast<double>(s.t_s.size()));
    s.accel_b_mps2.push_back(accel_inverse * f + e.accel_bias_mps2 +
                             e.accel_noise_mps2 * draw3());
    s.gyro_b_radps.push_back(gyro_inverse * w_body + e.gyro_bias_radps + e.g_sensitivity * f +
                             e.gyro_noise_radps * draw3());
    const double a = w_body.norm() * dt;
    if (a > 0) c = c * Eigen::AngleAxisd(a, w_body.normalized()).toRotationMatrix();
  };
  for (int k = 0; k < 2000; ++k) add(Vec3::Zero());
  for (int p = 0; p < poses; ++p) {
    const Vec3 axis = only_axis.norm() > 0 ? only_axis.normalized() : draw3().normalized();
    const Vec3 w = axis * angle(rng) / turn_s;
    for (int k = 0; k < static_cast<int>(turn_s / dt); ++k) add(w);
    for (int k = 0; k < static_cast<int>(still_s / dt); ++k) add(Vec3::Zero());
  }
  return s;
}

}  // namespace insmc::testing
