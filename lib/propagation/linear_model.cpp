#include "lib/propagation/linear_model.h"

#include <cmath>

#include "lib/alignment/alignment.h"
#include "lib/frames/frames.h"

namespace insmc {
namespace {

/// [v×] so that [v×] c = v × c; with the report's skew form,
/// paper_skew(c) v = v × c.
Mat3 cross_matrix(const Vec3& v) {
  Mat3 m;
  m << 0.0, -v.z(), v.y(), v.z(), 0.0, -v.x(), -v.y(), v.x(), 0.0;
  return m;
}

}  // namespace

LinearErrorModel::LinearErrorModel(System system, const ModelOptions& o, LinearModelForm form)
    : system_(system), options_(o), form_(form) {
  const double g = o.gravity_mps2, w = o.earth_rate_radps, r0 = o.radius_m;
  const double s = std::sin(o.latitude_rad), c = std::cos(o.latitude_rad);
  const RowMap zero = RowMap::Zero();
  c_prime_ = form.full_alignment ? full_switchover_misalignment(system, o)
                                 : paper_switchover_misalignment(system, o);
  initial_position_ = stack(pick(uncertainty_slot::kLatitudeError, r0), zero, pick(uncertainty_slot::kAltitudeError, -1.0));
  // (3.23) derived anew: δv = C_a'^i[(u)V + Ω_in δr^n + ΔΩ_in r^n + Z Ω_in r^n]
  // with δr^n = (0, 0, −δh), r^n = (0, 0, −r0): the east components are
  // δh ω_ie cos L0 and −r0 δL0 ω_ie sin L0 (Z Ω_in r^n = 0).
  // The report prints +2 r0 δL0 ω_ie sin L0 (errata.md#3-23).
  const double latitude_to_east_velocity = form.corrected_initial_velocity ? -r0 * w * s : 2 * r0 * w * s;
  initial_velocity_ = stack(pick(uncertainty_slot::kInitialVelocity + 0),
                            pick(uncertainty_slot::kInitialVelocity + 1) + pick(uncertainty_slot::kAltitudeError, w * c) +
                                pick(uncertainty_slot::kLatitudeError, latitude_to_east_velocity),
                            pick(uncertainty_slot::kInitialVelocity + 2));
  // Navigation-mode bias δf + (∂f_x, ∂f_y, 0) (3.18).
  nav_bias_ = stack(pick(uncertainty_slot::kAccelBias + 0) + pick(uncertainty_slot::kBiasChangeConst + 0) + pick(uncertainty_slot::kBiasChangeAlign + 0),
                    pick(uncertainty_slot::kAccelBias + 1) + pick(uncertainty_slot::kBiasChangeConst + 1) + pick(uncertainty_slot::kBiasChangeAlign + 1),
                    pick(uncertainty_slot::kAccelBias + 2));
  // α^n = (ξ g, −η g, 0) (2.8b).
  deflection_accel_ = stack(pick(uncertainty_slot::kDeflection + 0, g), pick(uncertainty_slot::kDeflection + 1, -g), zero);
  // Z^a of (3.20b) = paper_skew((0, δL0, 0)).
  latitude_angle_ = stack(zero, pick(uncertainty_slot::kLatitudeError), zero);
}

Sensitivity3 LinearErrorModel::drift_angles(double t) const {
  const ModelOptions& o = options_;
  const double w = o.earth_rate_radps, p = w * t;
  const double muy_factor = form_.corrected_muy ? std::cos(o.latitude_rad) : 1.0;
  // (3.11), (3.13): d = ω_do t + ω_MU (ω_ie t − sin ω_ie t)/ω_ie
  //                    + g·MUY cos L0 (1 − cos ω_ie t)/ω_ie.
  Sensitivity3 d = Sensitivity3::Zero();
  for (int k = 0; k < 3; ++k) {
    d(k, uncertainty_slot::kGyroDrift + k) = t;
    d(k, uncertainty_slot::kGyroMuDrift + k) = (p - std::sin(p)) / w;
    d(k, uncertainty_slot::kGyroMuyDrift + k) = muy_factor * (1.0 - std::cos(p)) / w;
  }
  return d;
}

Sensitivity3 LinearErrorModel::forcing(double t) const {
  const ModelOptions& o = options_;
  const Mat3 c_ap_n = C_ap_n(o.latitude_rad, o.earth_rate_radps * t);
  const Vec3 gravity_ap = o.gravity_mps2 * c_ap_n.col(2);  // C(t) g_e, g_e = (0, 0, g)
  const Mat3 vx = cross_matrix(gravity_ap);
  Sensitivity3 u = nav_bias_ - c_ap_n * deflection_accel_;
  // −(Z + D + Ψ) C g_e with each skew term paper_skew(c) C g_e = (C g_e) × c.
  u -= vx * (latitude_angle_ + drift_angles(t) + c_prime_);
  // −A C g_e: A = diag(a_x, a_y, a_z).
  for (int k = 0; k < 3; ++k) u(k, uncertainty_slot::kAccelScale + k) -= gravity_ap[k];
  // −3 δh/r0 C g_e (3.21).
  u.col(uncertainty_slot::kAltitudeError) -= 3.0 / o.radius_m * gravity_ap;
  return u;
}

std::vector<Sensitivity3> linear_position_maps(const LinearErrorModel& model,
                                               const std::vector<double>& times_s,
                                               double max_step_s) {
  return integrate_schuler_ode([&](double t) { return model.forcing(t); },
                               model.initial_position(), model.initial_velocity(), times_s,
                               model.options().schuler_radps(), max_step_s);
}

}  // namespace insmc
