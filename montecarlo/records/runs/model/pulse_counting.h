#pragma once
/// What ΔV pulse counting does to a run's observations (the truth level's
/// counters, simulator.h), as the gap diagnosis models it.
///
/// An accelerometer whose velocity increments are counted in pulses of w
/// (remainder carried, rounding at ±w/2, initial content the pulse phase ρ0 w)
/// gives the computer the velocity w N(t), N(t) = round(ρ0 + V(t)/w), V the
/// integrated specific force on the axis. Its velocity error
///   e(t) = w round(ρ0 + V/w) − V
/// is 0 until the first pulse, then an offset w ρ0 plus a sawtooth in V. On
/// an axis whose V grows fast (z: g; y: g cos L0 ω_ie t) the first pulse
/// comes within seconds and the sawtooth averages out of the position: the
/// report's "initial velocity error of up to half a pulse". On x, V grows
/// only as g cos L0 (ω_ie t)³/6 plus the run's own errors, so the offset
/// switches on minutes into the run, at a time set by each run's ρ0 and
/// errors, and the slow sawtooth moves the position by metres. Neither is a
/// linear function of x; their second moments over the runs are.
///
/// f rows: the counting error of a window, (e(t) − e(t − τ))/τ, whose
/// variance is w²/(6τ²) when the remainders at the window ends are
/// independent (two U(−½, ½) pulses).
/// r rows: r(t) = ∫₀ᵗ cos(ω_s (t − s)) e(s) ds, the Schuler response (3.24)
/// to a velocity error. Its covariance over the runs is computed by drawing
/// ρ0 and the run's errors (x from the priors, Gaussian with the same second
/// moments) and counting V(t) = nominal + the run's own increment exactly
/// (the sawtooth integrated in closed form within each step); the leading
/// components become columns, the rest row noise.
#include <Eigen/Core>

#include "lib/uncertainty/uncertainty_vector.h"
#include "montecarlo/records/runs/files/layout.h"

namespace insmc::runs {

/// Motion of the vehicle the counters count besides the specific force at
/// rest (sway): its velocity RMS per axis. Where that is at least half a
/// pulse, the counters move back and forth from the start, so the pulse
/// phase is an offset w ρ0 from t = 0 and the sawtooth averages out of the
/// position, instead of switching on when the nominal increment reaches a
/// pulse.
struct CountedMotion {
  Eigen::Vector3d velocity_rms_mps = Eigen::Vector3d::Zero();
};

struct PulseCounting {
  Eigen::MatrixXd columns;    ///< rows × k, each coefficient of unit variance
  Eigen::VectorXd noise_var;  ///< rows: f counting noise, r rest
};

/// The counting model of pulses of `pulse_mps` (0: a continuous output,
/// nothing) for a layout. `row_scale` (rows, > 0) sets which components of
/// the r-row covariance are kept as columns: those worth at least half a
/// row's scale² in total. Deterministic (a fixed internal stream).
PulseCounting pulse_counting(const Layout& layout, const RecordSite& site, double pulse_mps,
                             const UncertaintyVector& x_var, const Eigen::VectorXd& row_scale,
                             const CountedMotion& motion = {});

/// Velocity error of the counters [m/s]: w round(ρ0 + V/w) − V.
double counting_velocity_error(double velocity_mps, double phase, double pulse_mps);

/// ∫ of that error over a step on which V goes linearly from v0 to v1 [m].
double counting_velocity_error_integral(double v0_mps, double v1_mps, double step_s, double phase,
                                        double pulse_mps);

}  // namespace insmc::runs
