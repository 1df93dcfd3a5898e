#pragma once
/// The named effects of one truth run, realized: every random draw made and
/// every effect folded into a few additive terms that the simulator applies
/// without knowing which effect produced them (effects are independent and
/// combinable: their contributions add).
#include <Eigen/Core>
#include <optional>
#include <vector>

#include "lib/truth/grid_process.h"

namespace insmc {

/// amplitude · exp(−t/τ), per axis, t from switch-over [unit of amplitude].
struct ExponentialTerm {
  Vec3 amplitude = Vec3::Zero();
  double time_constant_s = 1.0;
};

/// One sinusoid of the sway displacement in the local-level frame n of the
/// site (north, east, down), fixed to the earth:
/// s(t) = amplitude · sin(2π t/period + phase).
struct SwayComponent {
  Vec3 amplitude_n_m = Vec3::Zero();
  double period_s = 1.0;
  double phase_rad = 0.0;
};

struct Perturbations {
  /// Pulse weight replacing TruthOptions::dv_pulse_mps (quantization) [m/s].
  std::optional<double> dv_pulse_mps;

  // ---- alignment and switch-over -------------------------------------------
  /// Added to the misalignment at switch-over C' (switch_transient,
  /// alignment_transient) [rad].
  Vec3 misalignment_step_rad = Vec3::Zero();
  /// Accelerometer bias and gyro drift present at the end of the alignment in
  /// addition to x's δf, ω_do: the value at t = 0 of the time-varying terms
  /// below, which the alignment loops null like δf and ω_do [m/s², rad/s].
  Vec3 alignment_bias_mps2 = Vec3::Zero();
  Vec3 alignment_drift_radps = Vec3::Zero();
  /// Accelerometer bias step at switch-over beyond ∂f (all axes) [m/s²].
  Vec3 nav_bias_step_mps2 = Vec3::Zero();

  // ---- earth ---------------------------------------------------------------
  /// Deflection of the vertical (ξ, η) added to x's [rad].
  Eigen::Vector2d deflection_rad = Eigen::Vector2d::Zero();
  /// J2 of the truth in excess of the navigation computer's.
  double extra_j2 = 0.0;

  // ---- instruments -----------------------------------------------------------
  /// Accelerometer second-order scale factor: f_m,k += k2_k f_k² [1/(m/s²)].
  Vec3 accel_quadratic_per_mps2 = Vec3::Zero();
  /// Anisoelastic drift ω_k += c f_i f_j with (k; i, j) = (x; y, z), (y; z, x),
  /// (z; x, y) [rad/s per (m/s²)²].
  double anisoelastic_radps_per_mps2sq = 0.0;
  /// Deterministic transients added to the bias [m/s²] and the drift [rad/s].
  std::vector<ExponentialTerm> bias_transients, drift_transients;
  /// Random processes on the noise grid: accelerometer bias [m/s²] and gyro
  /// drift [rad/s] (Gauss–Markov / random walk), platform angle random walk
  /// [rad, a rotation vector composed after the drift], accelerometer velocity
  /// random walk [m/s, added to the velocity increments].
  GridProcess bias_process, drift_process, angle_walk, velocity_walk;

  // ---- vehicle ---------------------------------------------------------------
  std::vector<SwayComponent> sway;
};

}  // namespace insmc
