#pragma once
/// The alignment loops in the time domain (chapter 2): the platform
/// misalignment C^a(t) during fine alignment from (2.9) (system 1) and (2.13)
/// (system 2), with the loop filters realized as state equations, from a
/// coarse-alignment error at its start, with the disturbing accelerations
/// (u)r̈ of (2.8). Its steady state is (2.10)/(2.14) (lib/alignment); after a
/// finite alignment time what has not settled stays in C' at switch-over.
///
/// Filters (the report gives their DC gains and their kind, §2.1, §2.2):
///  * system 1: F1 = F2 = F(0)/(1 + τ_f p), τ_f = 10 s ("a low pass filter
///    with a 10 second time constant, a well damped loop", F(0)/ω_ie = 500);
///    F_T a constant gain F_T(0) (infinite: the theodolite holds C_z).
///  * system 2: F1 = K1 (1 + 1/(T1 p)) proportional plus integral with
///    K1 = F(0) (T1 = 60 s: damping 0.74); F2 = F2(0)/(1 + τ_f p);
///    F3 = K3 (1 + 1/(T3 p)), the gyrocompass, not given by the report: K3
///    and T3 place the azimuth loop's poles (C_y, C_z and the integral, with
///    F2 ≈ F2(0)) at one triple pole p0 = F2(0)/3 — critically damped,
///    1/p0 = 82 s for F2(0) = 500 ω_ie: K3 = 3 p0²/(ω_ie cos L0), T3 = 3/p0.
#include <functional>

#include "lib/common/model_options.h"
#include "lib/common/system.h"
#include "lib/frames/frames.h"
#include "lib/uncertainty/uncertainty_vector.h"

namespace insmc {

struct AlignmentLoopSettings {
  double duration_s = 900.0;  ///< fine-alignment time; > 0
  /// C^a at the start of the fine alignment (coarse-alignment leftovers) [rad].
  Vec3 initial_misalignment_rad = Vec3(1e-4, 1e-4, 5e-3);
  double level_filter_s = 10.0;            ///< τ_f of the low-pass filters; > 0
  double level_integral_s = 60.0;          ///< T1 of system 2's F1; > 0
  /// Window at the end of the alignment over which the commands and the
  /// accelerometer outputs are averaged (the measurements of 5.4); > 0.
  double average_s = 600.0;
  double step_s = 0.5;  ///< RK4 step; (0, 5]
};

/// Throws InputError naming the first field out of range.
void validate(const AlignmentLoopSettings& settings);

struct AlignmentLoopRun {
  Vec3 misalignment_rad = Vec3::Zero();  ///< C^a at the end (before the switch-over step ζ_r)
  /// Torquer command rates less the earth-rate command, ω_c of (5.14),
  /// averaged over the last `average_s` [rad/s].
  Vec3 mean_command_radps = Vec3::Zero();
  /// Accelerometer output errors Δf_m of (5.18), (5.19), averaged likewise [m/s²].
  Vec3 mean_accel_output_mps2 = Vec3::Zero();
};

/// Simulates the loops for the uncertainties x (SI, uncertainty_slot order) with the
/// options' gravity as the sensed g. `disturbance_n_mps2(t)`, t ∈ [−duration, 0]
/// (switch-over at 0), is (u)r̈ in the local-level frame; empty = none.
AlignmentLoopRun simulate_alignment_loops(System system, const ModelOptions& model,
                                          const AlignmentLoopSettings& settings, const UncertaintyVector& x,
                                          const std::function<Vec3(double)>& disturbance_n_mps2 = {});

}  // namespace insmc
