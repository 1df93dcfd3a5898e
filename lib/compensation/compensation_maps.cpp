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

using scheme_terms::ramp_response;
using scheme_terms::step_response;

// Response of the Schuler loop ÿ + ω_s² y = a(τ) from rest to τ²/2 (fig. 3.3).
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
  v.middleCols<3>(uncertainty_slot::kInitialVelocity).setZero();
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
      r.middleCols<3>(uncertainty_slot::kResetPositionError) += std::cos(ws * tau) * Mat3::Identity();
      r.middleCols<3>(uncertainty_slot::kResetVelocityError) += std::sin(ws * tau) / ws * Mat3::Identity();
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
  r_reset.middleCols<3>(uncertainty_slot::kResetPositionError) += Mat3::Identity();
  v_reset.middleCols<3>(uncertainty_slot::kResetVelocityError) += Mat3::Identity();
  return integrate_schuler_ode([&](double t) { return model.forcing(t); }, r_reset, v_reset, times,
                               m.schuler_radps(), 2.0, T);
}

/// Puts an uncompensated map of x into an extended map; after a realignment
/// the per-alignment slots come from the fresh draws instead.
ExtendedMap extend(const Sensitivity3& s, bool realigned) {
  ExtendedMap e = ExtendedMap::Zero();
  e.leftCols<uncertainty_slot::kDim>() = s;
  if (realigned) {
    for (const RealignedSlot& r : kRealignedSlots) {
      e.col(r.z_index) = s.col(r.x_index);
      e.col(r.x_index).setZero();
    }
    // The realignment keeps the theodolite's (u)ψ and adds its re-sighting
    // change δψ_r: the same column (zero for system 2).
    e.col(uncertainty_slot::kRealignAzimuthError) = s.col(uncertainty_slot::kTheodolite);
  }
  return e;
}

}  // namespace

SchemeMaps scheme_position_maps(Scheme scheme, System system, Fidelity fidelity, const ModelOptions& m,
                                const TestRunOptions& test, const std::vector<double>& taus, SchemeForms forms) {
  INSMC_ASSERT(fidelity != Fidelity::kTruth, "scheme maps exist for the linear-in-x levels only");
  const double ws = m.schuler_radps(), T = test.duration_s;
  const SchemeDefinition& definition = scheme.definition();
  SchemeMaps out;
  out.ready_time_s = ready_time_s(scheme, T, test.realignment_duration_s);
  out.frame_time_offset_s = frame_time_offset_s(scheme, T);
  const std::vector<Sensitivity3> s = definition.resets_at_test_end ? reset_propagation(system, fidelity, m, T, taus, forms)
                                                                    : position_maps(system, fidelity, m, taus);
  const std::vector<Mat3> torquer =
      definition.uses_alignment_data ? torquer_response(fidelity, m, taus) : std::vector<Mat3>(taus.size(), Mat3::Zero());
  for (size_t n = 0; n < taus.size(); ++n) {
    const double tau = taus[n];
    ExtendedMap e = extend(s[n], definition.realigns);
    // The resets at T leave the velocity wiggle (u)V(T) in the integrators (5.8), (5.11).
    if (definition.resets_at_test_end) e.middleCols<3>(z_slot::kWiggleAtT) = std::sin(ws * tau) / ws * Mat3::Identity();
    const ShortRunFunctions paper =
        fidelity == Fidelity::kPaper ? short_run_functions_3_29(tau, m) : ShortRunFunctions{0, 0, 0, 0, 0, 0};
    definition.position_map({system, fidelity, forms, m, T, tau, s[n], torquer[n], paper}, e);
    out.position.push_back(e);
  }
  return out;
}

}  // namespace insmc
