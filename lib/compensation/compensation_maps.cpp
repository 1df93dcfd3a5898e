#include "lib/compensation/compensation_maps.h"

#include <cmath>

#include "lib/common/assert.h"
#include "lib/frames/frames.h"
#include "lib/propagation/closed_form.h"
#include "lib/propagation/linear_model.h"
#include "lib/propagation/paper_model.h"
#include "lib/propagation/position_maps.h"

namespace insmc {
namespace {

// Responses of the Schuler loop ÿ + ω_s² y = a(τ) from rest to a unit
// step, ramp τ and τ²/2 (Laplace pairs of fig. 3.3).
double step_response(double tau, double ws) { return (1 - std::cos(ws * tau)) / (ws * ws); }
double ramp_response(double tau, double ws) { return (tau - std::sin(ws * tau) / ws) / (ws * ws); }
double quadratic_response(double tau, double ws) { return (tau * tau / 2 - step_response(tau, ws)) / (ws * ws); }

/// Position response to unit torquer rates (point 4) applied from t = 0 in
/// the navigation mode only (the alignment is not affected): 3×3 per time.
std::vector<Mat3> torquer_response(Fidelity fidelity, const ModelOptions& m, const std::vector<double>& times) {
  std::vector<Mat3> out;
  if (fidelity == Fidelity::kPaper) {
    // The drift terms of U3, U4, U5 that come from the navigation mode:
    // K2 → U3 = (1/ω_ie)[ω_doy; −ω_dox; 0]; 2K5 → U4 = (2 cos L0/ω_ie)[ω_doz; 0; −ω_dox];
    // 3K6 → U5 = (3 cos L0/ω_ie)[−ω_doy cos L0; ω_dox cos L0 − ω_doz sin L0; ω_doy sin L0].
    const double w = m.earth_rate_radps, s = std::sin(m.latitude_rad), c = std::cos(m.latitude_rad);
    Mat3 u3, u4, u5;
    u3 << 0, 1, 0, -1, 0, 0, 0, 0, 0;
    u4 << 0, 0, 2 * c, 0, 0, 0, -2 * c, 0, 0;
    u5 << 0, -3 * c * c, 0, 3 * c * c, 0, -3 * c * s, 0, 3 * c * s, 0;
    for (double t : times) {
      const ShortRunFunctions f = short_run_functions_3_29(t, m);
      out.push_back(m.radius_m / w * (f.u3 * u3 + f.u4 * u4 + f.u5 * u5));
    }
    return out;
  }
  // Linear level: drift angles d = ω_cp t give the forcing −[v(t)×] d with
  // v(t) = C_n^{a'}(t) g_e (3.24).
  auto forcing = [&](double t) {
    Sensitivity3 u = Sensitivity3::Zero();
    const Vec3 v = m.gravity_mps2 * C_ap_n(m.latitude_rad, m.earth_rate_radps * t).col(2);
    for (int k = 0; k < 3; ++k) u.col(k) = -t * v.cross(Vec3::Unit(k));
    return u;
  };
  for (const auto& s : integrate_schuler_ode(forcing, Sensitivity3::Zero(), Sensitivity3::Zero(), times,
                                             m.schuler_radps()))
    out.push_back(s.leftCols<3>());
  return out;
}

/// Velocity error the computer sets for a stationary vehicle, without the
/// wiggle (u)V: the latitude and altitude terms of (3.23).
Sensitivity3 computed_velocity_error(const Sensitivity3& initial_velocity) {
  Sensitivity3 v = initial_velocity;
  v.middleCols<3>(ux::kInitialVelocity).setZero();
  return v;
}

/// δr after position and velocity resets at T (points 5, 6), per unit x, at
/// T + τ: the integrators get the values the computer calculates for a
/// stationary vehicle, i.e. the errors of (3.22), (3.23) turned with the
/// earth to time T; the uncompensated forcing goes on.
std::vector<Sensitivity3> reset_propagation(System system, Fidelity fidelity, const ModelOptions& m, double T,
                                            const std::vector<double>& taus, SchemeForms forms) {
  std::vector<Sensitivity3> out;
  if (fidelity == Fidelity::kPaper) {
    // Fig. 3.3 from T with the loop state y = δr − δr(0) reset to 0 and its
    // rate to the computed velocity error; forcing g[U2 + U3 ω_ie t + U4 ω_ie² t²/2]
    // in powers of τ = t − T; U5 kept at the output as in (3.29).
    const ShortRunMatrices sr = paper_short_run_matrices(system, m);
    const double g = m.gravity_mps2, w = m.earth_rate_radps, ws = m.schuler_radps();
    const Sensitivity3 a0 = g * (sr.u2 + w * T * sr.u3 + w * w * T * T / 2 * sr.u4);
    const Sensitivity3 a1 = g * (w * sr.u3 + w * w * T * sr.u4);
    const Sensitivity3 a2 = g * w * w * sr.u4;
    const Sensitivity3 v0 = computed_velocity_error(sr.initial_velocity_mps);
    for (double tau : taus) {
      // (5.8) carries U5 ω_ie³t³/6 from the switch-over: after the resets its
      // growth continues, (T + t')³ − T³; (5.9), (5.11b) print t'³ (errata.md#5-9).
      const double t = T + tau;
      const double p3 = forms == SchemeForms::kPrinted ? std::pow(w * tau, 3) : std::pow(w * t, 3) - std::pow(w * T, 3);
      Sensitivity3 r = sr.initial_position_m + std::sin(ws * tau) / ws * v0 + step_response(tau, ws) * a0 +
                       ramp_response(tau, ws) * a1 + quadratic_response(tau, ws) * a2 + m.radius_m * p3 / 6 * sr.u5;
      // The resets' own errors, as δr̂(T) and δṙ̂(T) enter (5.8): cos ω_s t', sin ω_s t' / ω_s.
      r.middleCols<3>(ux::kResetPositionError) += std::cos(ws * tau) * Mat3::Identity();
      r.middleCols<3>(ux::kResetVelocityError) += std::sin(ws * tau) / ws * Mat3::Identity();
      out.push_back(r);
    }
    return out;
  }
  const LinearErrorModel model(system, m);
  const Mat3 turn = C_ap_n(m.latitude_rad, m.earth_rate_radps * T);
  std::vector<double> times;
  for (double tau : taus) times.push_back(T + tau);
  // The integrators' state after the reset: the computed values (with the
  // resets' own errors) less the truth.
  Sensitivity3 r_reset = turn * model.initial_position(), v_reset = turn * computed_velocity_error(model.initial_velocity());
  r_reset.middleCols<3>(ux::kResetPositionError) += Mat3::Identity();
  v_reset.middleCols<3>(ux::kResetVelocityError) += Mat3::Identity();
  return integrate_schuler_ode([&](double t) { return model.forcing(t); }, r_reset, v_reset, times,
                               m.schuler_radps(), 2.0, T);
}

/// Puts an uncompensated map of x into an extended map; after a realignment
/// the per-alignment slots come from the fresh draws instead.
ExtendedMap extend(const Sensitivity3& s, bool realigned) {
  ExtendedMap e = ExtendedMap::Zero();
  e.leftCols<ux::kDim>() = s;
  if (realigned) {
    for (const RealignedSlot& r : kRealignedSlots) {
      e.col(r.z_index) = s.col(r.x_index);
      e.col(r.x_index).setZero();
    }
  }
  return e;
}

}  // namespace

Eigen::Matrix3d torquer_rates_from_u3(System system, const ModelOptions& m) {
  const double w = m.earth_rate_radps;
  Eigen::Matrix3d t = Eigen::Matrix3d::Zero();
  t(0, 1) = w;  // ω_cp,x = ω_ie Û3y
  if (system == System::kTheodolite) t(1, 0) = -w;  // ω_cp,y = −ω_ie Û3x (5.5a)
  return t;
}

Eigen::Matrix3d combined_integrator_selection(System system) {
  Eigen::Matrix3d s = Eigen::Matrix3d::Zero();
  s(2, 2) = 1;
  if (system == System::kGyrocompass) s(0, 0) = 1;
  return s;
}

SchemeMaps scheme_position_maps(Scheme scheme, System system, Fidelity fidelity, const ModelOptions& m,
                                const TestRunOptions& test, const std::vector<double>& taus, SchemeForms forms) {
  INSMC_ASSERT(fidelity != Fidelity::kTruth, "scheme maps exist for the linear-in-x levels only");
  const double g = m.gravity_mps2, w = m.earth_rate_radps, ws = m.schuler_radps(), T = test.duration_s;
  SchemeMaps out;
  out.ready_time_s = ready_time_s(scheme, T, test.realignment_duration_s);
  out.frame_time_offset_s = frame_time_offset_s(scheme, T);
  const std::vector<Sensitivity3> s = resets_at_test_end(scheme) ? reset_propagation(system, fidelity, m, T, taus, forms)
                                                                 : position_maps(system, fidelity, m, taus);
  const std::vector<Mat3> torquer = uses_alignment_data(scheme) ? torquer_response(fidelity, m, taus) : std::vector<Mat3>{};
  const Mat3 w_from_u3 = torquer_rates_from_u3(system, m);
  for (size_t n = 0; n < taus.size(); ++n) {
    const double tau = taus[n], r0s = step_response(tau, ws), r1s = ramp_response(tau, ws);
    const Mat3 I = Mat3::Identity();
    ExtendedMap e = extend(s[n], realigns(scheme));
    switch (scheme) {
      case Scheme::kNone: break;
      case Scheme::k5_1_1:  // (5.2) at point 2, (5.3) through integrators
        e.middleCols<3>(ez::kU2) = -g * r0s * I;
        e.middleCols<3>(ez::kU3) = -g * w * r1s * I;
        break;
      case Scheme::k5_1_2:
      case Scheme::kCombined: {
        e.middleCols<3>(ez::kU2) = -g * r0s * I;
        // (5.5): torquer rates active through the realignment and after it,
        // i.e. the level-platform drift becomes ω_do + ω_cp everywhere.
        e.middleCols<3>(ez::kU3) = s[n].middleCols<3>(ux::kGyroDrift) * w_from_u3;
        if (scheme == Scheme::kCombined)
          e.middleCols<3>(ez::kU3) += -g * w * r1s * combined_integrator_selection(system);
        break;
      }
      case Scheme::k5_2:  // (5.8): point 2 −g(Û2 + Û3 ω_ie T), integrators −g ω_ie Û3, resets
        e.middleCols<3>(ez::kU2) = -g * r0s * I;
        e.middleCols<3>(ez::kU3) = -g * w * (T * r0s + r1s) * I;
        e.middleCols<3>(ez::kWiggleAtT) = std::sin(ws * tau) / ws * I;
        break;
      case Scheme::k5_3:  // (5.11): point 2 −Δf̂(T), integrators −g ω_ie Û3, resets
        e.middleCols<3>(ez::kDfT) = -r0s * I;
        e.middleCols<3>(ez::kU3Accel) = -g * w * r1s * I;
        e.middleCols<3>(ez::kWiggleAtT) = std::sin(ws * tau) / ws * I;
        break;
      case Scheme::k5_4: {  // (5.15), (5.16) at point 4 from t = 0; (5.19) at point 2
        Mat3 select = I;
        if (system == System::kGyrocompass) select(1, 1) = 0;  // (5.15c): no y estimate
        e.middleCols<3>(ez::kTorquerCommands) = torquer[n] * select;
        // ω_ie E4 of (5.15) enters the applied rates as the commands do.
        e.middleCols<3>(ux::kAlignDriftError) = torquer[n] * select;
        e.middleCols<3>(ez::kAlignAccel) = -r0s * I;
        // (5.20) as printed: U'2_z = δg − 2δh/r0, where −Δf_m/g at point 2 gives
        // −δg/g − 2δh/r0; with δg/g = −3δh/r0 (§4.1) the printed z row is
        // −5δh/r0 against the derived +δh/r0 (errata.md#5-20). (ε5's sign, the
        // other difference, is immaterial: a zero-mean measurement error.)
        if (fidelity == Fidelity::kPaper && forms == SchemeForms::kPrinted)
          e(2, ux::kAltitudeError) += -6.0 * (1 - std::cos(ws * tau));  // r0 (−6δh/r0)(1 − cos ω_s t)
        break;
      }
    }
    out.position.push_back(e);
  }
  return out;
}

}  // namespace insmc
