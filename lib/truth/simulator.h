#pragma once
/// The `truth` fidelity level (docs/truth-vs-models.md): a nonlinear simulation
/// of the space-stabilized INS of the report on a stationary base, making none
/// of the report's approximations. It stands in for the real system and is the
/// data source of the sim-to-real gap diagnosis.
///
/// What is simulated (t = 0 at the switch to navigation mode):
///  * the vehicle at rest at plumb-line latitude L0, longitude 0, distance r0
///    from the earth's centre, on the rotating earth (earth_model.h: μ = g r0²,
///    spherical gravitation, optionally J2; deflection of the vertical ξ, η as a
///    gravity anomaly of the site); truth in the inertial frame i;
///  * the platform attitude C_a^i as a unit quaternion, integrated from the gyro
///    rates (no small-angle approximation): fixed drift plus mass-unbalance
///    drift MU f^a from the actual specific force in the actual platform frame
///    (3.9)–(3.10), plus the torquer-command hook. Initial attitude: the
///    steady-state misalignment at switch-over C' (2.18a) (full alignment
///    equations, lib/alignment) turning the true local-level frame a' as the
///    loops leave it (switchover_attitude below: azimuth C'_z, then the tilt
///    that meets the linear horizontal specific force exactly);
///  * accelerometers f_m = (I + A) f^a + δf + (∂f_x, ∂f_y, 0) (3.14)–(3.18),
///    integrated to velocity increments and quantized into pulses of weight
///    dv_pulse_mps with the remainder carried (rounding quantizer: a pulse
///    each time the accumulator passes ±w/2; its initial content is the
///    pulse phase);
///  * a navigation computer in i: r̈_c = G_c(r_c) + Ĉ_a^i ΔV-rate (3.20),
///    Ĉ_a^i from L̂0 = L0 + δL0, computed gravitation with external altitude
///    |r| ≈ r0 + δh (3.21), initial position and velocity from L̂0 and the
///    external altitude as the computer would (3.22)–(3.23) (with the same
///    plumb-line-to-position map as the truth, so every uncertainty zero gives
///    no error), plus the velocity wiggle (u)V. The computer integrates the
///    pulses exactly (an ideal computer limited only by the pulse weight):
///    its velocity is Ĉ w N(t) + ∫ G_c, N(t) the pulse count.
///
/// How the uncertainties of x enter (the same definitions as
/// lib/propagation/linear_model.cpp, which this level must agree with):
///  * ω_MU and g·MUY build the mass-unbalance matrix MUX_k = 0,
///    MUY_k = g·MUY_k / g_s, MUZ_k = ω_MU,k / (g_s cos² L0), and
///    ω_AI = ω_do − MU f_level, f_level = (0, 0, −g_s), g_s the specific force
///    at the site: then the level-platform drift is ω_do exactly and (3.13a)
///    gives back ω_MU; only these combinations enter to first order.
///  * The alignment (steady state) is evaluated with g_s: the leveling loops
///    null the measured specific force, so δf and ξ, η cancel exactly as in the
///    linear model (with the model's g instead, 0.17% of δf would survive at
///    45°: 11 m of Schuler oscillation per mg).
///  * The accelerometer output error of the records, Δf^a = f_m − f̂ (4.2),
///    uses the data analysis' expected specific force of (4.1)–(4.1b):
///    f̂ = Ĉ_i^{a'} C_n^i(t) (0, 0, −ĝ) with Ĉ_i^{a'} from L̂0 and
///    ĝ = g_s (1 − 3 δh/r0) (§4.1's δg/g = −3 δh/r0), averaged over the filter
///    interval τ ending at each output time.
///
/// Numerics: the navigation error δr = r_c − r (exact difference, no
/// linearization) and the platform are integrated together by classical RK4
/// with steps of at most step_s landing on every output time (halving the
/// 5 s default changes δr by < 1e-6 m continuous, < 1e-3 m with pulses).
/// Stochastic effects are realized on a fixed noise grid; terms that vary
/// faster than the step enter by their exact integrals over it (split from
/// the RK4 step): the random accelerometer processes and the sway motion as
/// velocity increments, the random platform rotations (drift instability,
/// angle random walk) as the exact rotation of the platform and the force
/// −θ(s) × f^a it makes the accelerometers see within the step. Pulses: the
/// remainder's time integral (the computer's position lag) uses the pulse
/// crossing times of a quadratic accumulator path when few pulses fall in a
/// step, and the equidistributed-remainder formula when many do.
///
/// Second-order terms the linear model drops (measured, tests/unit/lib/truth):
/// the vertical r0 (θ²/2)(1 − cos ω_s t) of a leveling tilt θ (6.4 m at 1 mg
/// of δf_x), and the finite-rotation product ½ C' × d of misalignment and
/// drift angle (171 m in system 2 for ω_doy = 10 meru, where C'_z = 14 mrad).
#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "lib/alignment/alignment_loops.h"
#include "lib/common/input_error.h"
#include "lib/common/model_options.h"
#include "lib/common/system.h"
#include "lib/frames/frames.h"
#include "lib/truth/effect.h"
#include "lib/uncertainty/uncertainty_vector.h"

namespace insmc {

/// A compensation signal at point 2: zero before `start_s`, then
/// step_mps2 + ramp_mps3 (t − start_s) [m/s²] in the platform frame.
struct AccelCompensation {
  double start_s = 0.0;
  Vec3 step_mps2 = Vec3::Zero();
  Vec3 ramp_mps3 = Vec3::Zero();
  bool active() const { return !step_mps2.isZero(0.0) || !ramp_mps3.isZero(0.0); }
  Vec3 at(double t_s) const { return step_mps2 + (t_s - start_s) * ramp_mps3; }
};

struct TruthOptions {
  /// The site, loop gains and constants shared with the linear model.
  ModelOptions model;
  /// Alignment concept (chapter 2).
  System system = System::kTheodolite;
  /// ΔV pulse weight [m/s] (the records' dv_pulse_mps, docs/records.md; the
  /// report's 0.1 ft/s); 0 = a
  /// continuous accelerometer output. ≥ 0. The quantization effect overrides it.
  double dv_pulse_mps = 0.1 * kFtpsToMps;
  /// τ, the filter-box interval of the accelerometer data (fig. 5.2) [s]; > 0.
  double filter_interval_s = 10.0;
  /// Largest integration step [s]; (0, 60]. RK4 error scales as step⁴:
  /// 5 s keeps the navigation error within millimetres of the converged value
  /// (halving it changes δr by < 1 cm over 2 h; tests/unit/lib/truth).
  double step_s = 5.0;
  /// Spherical gravitation (false) or with the earth's J2 (true), in both the
  /// truth and the computer (the gravity_model effect makes them differ).
  bool j2_gravity = false;
  /// Initial content ρ0 of each accelerometer's pulse accumulator, in pulses,
  /// [−0.5, 0.5) (the pulse phase). Counted at the first pulse, it is an
  /// initial velocity error of ρ0 once pulses are dense (a Schuler
  /// oscillation of up to 12 m at half a 0.1 ft/s pulse).
  Vec3 pulse_phase = Vec3::Zero();
  /// Grid of the effects' random processes [s]; > 0.
  double noise_grid_s = 1.0;
  /// Named effects, applied together.
  std::vector<EffectSpec> effects;
  /// Injection point 4 (fig. 5.1): gyro torquer command rates added to the
  /// platform's rates in the navigation mode, in the platform frame [rad/s];
  /// empty = none. A hook for the compensation schemes.
  std::function<Vec3(double t_s)> torquer_command_radps;
  /// Injection point 2 (fig. 5.1), and the integrators into it: a signal the
  /// computer adds to the accelerometer outputs it integrates (platform
  /// frame), step + ramp·(t − start) from `start_s` on. The instruments and
  /// their pulses (and so the recorded Δf^a) are not affected.
  AccelCompensation accel_compensation;
  /// The fine alignment: nullopt (default) = the loops in steady state
  /// (2.10)/(2.14); otherwise simulated in the time domain over the given
  /// alignment time from a coarse error (alignment_loops.h), what has not
  /// settled staying in C' at switch-over, with the sway effect's
  /// accelerations as the disturbance (u)r̈ of (2.8). (A realignment of
  /// 5.1.x starts from the navigating platform and is taken in steady state.)
  std::optional<AlignmentLoopSettings> alignment_loops;
  /// Points 5, 6 (fig. 5.1): at this time [s] the computer's velocity and
  /// position integrators are set to the values it calculates for a
  /// stationary vehicle ((3.22), (3.23) turned with the earth, no wiggle), and
  /// its pulse bookkeeping restarts; negative = no reset. An output at this
  /// very time gives the error just after the reset.
  double reset_at_s = -1.0;
};

/// The truth simulator's site latitude limit, |L0| <= 89 deg.
inline constexpr double kMaxTruthLatitudeDeg = 89.0;
/// The error for a site latitude beyond it, named as the caller's input
/// (`field`: the command-line option or the record key); nullopt within.
std::optional<InputError> truth_latitude_error(double latitude_rad, std::string field);

/// Checks every constraint on the options (and each effect); throws
/// InputError naming the field and what it allows.
void validate(const TruthOptions& options);

using PulseCount3 = Eigen::Matrix<std::int64_t, 3, 1>;

/// One truth run sampled at the requested times.
struct TruthRun {
  std::vector<double> t_s;                 ///< output times, s since switch-over
  std::vector<Vec3> position_error_ap_m;   ///< δr^{a'} = r_c − r in a' (3.2) [m]
  /// Δf^a over the filter interval (t − τ, t] [m/s²]; NaN where t < τ.
  std::vector<Vec3> accel_error_ap_mps2;
  /// Accelerometer pulses over (t − τ, t] (zero where t < τ or with a
  /// continuous output).
  std::vector<PulseCount3> pulse_counts;

  double dv_pulse_mps = 0.0;          ///< pulse weight used (after effects)
  double site_gravity_mps2 = 0.0;     ///< g_s = |f| at the site
  Vec3 switchover_misalignment_rad = Vec3::Zero();  ///< C' applied (incl. effects)
  /// What the alignment electronics saw, unquantized, with the effects'
  /// alignment-phase terms and the site's g_s: the torquer commands ω_c
  /// (5.14) less the earth-rate command and the accelerometer outputs Δf_m
  /// (5.19) — steady-state values, or with time-domain loops their averages
  /// over the end of the alignment (the measurements of scheme 5.4).
  Vec3 alignment_command_radps = Vec3::Zero();
  Vec3 alignment_accel_output_mps2 = Vec3::Zero();
};

/// Simulates one run for the uncertainties `x` (SI, uncertainty_slot order) and the effects
/// of `options`, sampled at `output_times_s` (ascending, ≥ 0). `noise` is
/// required when a random effect is on (see noise.h). Deterministic: the same
/// inputs give bit-identical results.
TruthRun simulate_truth(const TruthOptions& options, const UncertaintyVector& x,
                        const std::vector<double>& output_times_s, const NormalSource& noise = {});

/// C_a^{a'} at switch-over for the misalignment C' (2.18) and the true
/// specific force f^{a'} at the site, as the alignment loops leave the
/// platform: the azimuth loop turns it by C'_z about the vertical, the leveling
/// loops tilt it until the horizontal specific force in the platform is the
/// value they null to, f^a_h = (f^{a'} − C' × f^{a'})_h — the first-order
/// relation of (2.17), (3.16), now met exactly. (A plain rotation vector
/// exp([C'×]) would add spurious horizontal forces g C'_z C'_{x,y}/2.)
/// Precondition: |f^a_h| < |f^{a'}|.
Mat3 switchover_attitude(const Vec3& c_prime, const Vec3& f_ap);

/// Times closer than this are the same instant of a lattice: k × interval
/// carries a round-off of a few ulp (3e-11 s at 48 h), far below it, and
/// intervals are at least 0.1 ms, far above it.
inline constexpr double kLatticeTolS = 1e-9;

/// t = interval, 2 interval, … up to `end` (and `end` itself) [s]; with
/// include_zero also t = 0. Every time lies in [0, end]: the lattice point
/// within kLatticeTolS of `end` is `end` exactly (4608 ms × 37500 is
/// 172800.00000000003 s in doubles, past a 48 h record's last instant).
std::vector<double> uniform_times(double end_s, double interval_s, bool include_zero = true);

}  // namespace insmc
