#pragma once
/// Preflight test-run observables on a stationary base (chapter 4): the
/// accelerometer output error Δf^a(t) and the change of the position error
/// Δr^{a'}(t) = δr^{a'}(t) − δr(0)^{a'}, per unit of each uncertainty, and
/// the ΔV pulse-count resolution limits (4.6).
#include <cmath>

#include "lib/common/model_options.h"
#include "lib/propagation/linear_model.h"
#include "lib/propagation/paper_model.h"

namespace insmc {

/// A1 = U2 + δr(0)/r0 (4.4b), dimensionless.
Sensitivity3 paper_a1(const ShortRunMatrices& m, const ModelOptions& options);

/// (4.4): Δf^a = g{A1 + U3 ω_ie t + U4 ½ω_ie² t²} [m/s²] (no sway).
Sensitivity3 paper_accelerometer_error(const ShortRunMatrices& m, double t_s,
                                       const ModelOptions& options);

/// (4.5): Δr^{a'} = δV(0) sin(ω_s t)/ω_s + r0 U2(1 − cos ω_s t)
///        + r0 (ω_ie/ω_s) U3 (ω_s t − sin ω_s t) + r0 (ω_ie/ω_s)² U4 [½ω_s²t² − (1 − cos ω_s t)] [m].
Sensitivity3 paper_test_position_change(const ShortRunMatrices& m, double t_s,
                                        const ModelOptions& options);

/// (4.2) at the linear level: Δf^a(t) equals the forcing u(t) of (3.24)
/// (δg/g = −3δh/r0, §4.1) [m/s²].
inline Sensitivity3 linear_accelerometer_error(const LinearErrorModel& model, double t_s) {
  return model.forcing(t_s);
}

/// Resolution limits of (4.6) for pulse weight ΔV [m/s] and test duration T [s]:
/// the smallest A1_k, U3_k, U4_k giving three pulses in T.
struct ResolutionLimits {
  double a1, u3, u4;  ///< dimensionless
};
ResolutionLimits pulse_resolution_limits(double dv_pulse_mps, double test_duration_s,
                                         const ModelOptions& options);

/// The mean of a signal over `span_s` as a pulse counter of weight `pulse`
/// reports it, less the `known` part of the signal: the counter sees
/// (known + error)·span on top of its starting remainder phase01·pulse
/// (phase01 ∈ [0, 1)) and counts whole pulses (§4.3, (5.14), (5.18)).
/// pulse = 0: a continuous output, the error itself.
inline double counted_mean(double error, double known, double span_s, double pulse, double phase01) {
  if (!(pulse > 0)) return error;
  return pulse * std::floor(((known + error) * span_s + phase01 * pulse) / pulse) / span_s - known;
}

/// The position computer's output at resolution q (nearest; q = 0: exact).
inline double at_resolution(double value, double q) { return q > 0 ? q * std::round(value / q) : value; }

}  // namespace insmc
