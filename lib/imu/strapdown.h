#pragma once
/// A strapdown navigation computer in the inertial frame, on a stationary
/// base, fed by raw IMU samples (lib/imu/imu_samples.h): the path from real
/// data to records of format v1 (docs/records.md, docs/real-data/import.md).
///
/// Why it behaves as the report's space-stabilized platform: the computer
/// keeps the attitude C_b^â of the sensor body b relative to a virtual
/// platform â that is fixed in inertial space, integrating the measured gyro
/// rates (which include the earth rate the sensor turns with). â plays the
/// platform a; at t = 0 the alignment makes it the ideal instrument frame a'
/// (x north, y east, z down at t = 0, then fixed in i; lib/frames/frames.h).
/// The accelerometer outputs rotated into â are the platform accelerometers'
/// outputs f^a, and the navigation in i (3.20)–(3.21) is the report's.
///
/// What differs from a platform: the instrument errors are fixed in the body,
/// which turns with the earth relative to â (26° in 105 min), so a constant
/// sensor bias is seen in a' as a vector turning at ω_ie; the platform's
/// gyros and accelerometers do not turn.
///
/// Stages of one run (t = 0 at the switch to navigation):
///  1. Alignment over [−align_duration, 0) (system 1 of chapter 2): leveling
///     from the mean measured specific force (the leveling loops null the
///     horizontal accelerometer outputs, so horizontal biases become a tilt
///     and are nulled at t = 0, as in (2.9)–(2.10)); azimuth from the user
///     (the theodolite of system 1, (2.11)); latitude and altitude from the
///     user. Gyro bias estimate: the window's mean gyro output minus the earth
///     rate the aligned body must sense.
///  2. Navigation from t = 0: attitude from the gyros (bias removed or kept),
///     r̈_c = G_c(r_c) + Ĉ_a^i f^a (3.20) with the computed gravitation
///     G_c = −(μ/R³) r_c at the external radius R = r0 + altitude (3.21,
///     linear in r_c: the vertical channel oscillates at the Schuler
///     frequency as the report's does, instead of diverging), from the
///     site's position and velocity (3.22)–(3.23) with zero error.
///  3. Outputs at τ, 2τ, …, T + nav: the accelerometer output error
///     Δf^a = f^a − f̂^{a'} (4.2) over the filter interval (t − τ, t], f̂ the
///     expected specific force of (4.1) averaged over the interval; the
///     position error δr^{a'} = C_i^{a'} (r_c − r) (4.5), r the site turning
///     with the earth.
///
/// Earth: the model of lib/truth/earth_model.h (sphere, μ = g r0²); the site
/// is at plumb-line latitude L0, distance r0 + altitude from the centre.
#include <cstddef>
#include <optional>
#include <string_view>
#include <vector>

#include "lib/common/input_error.h"
#include "lib/frames/frames.h"
#include "lib/imu/imu_samples.h"
#include "lib/units/units.h"

namespace insmc {

/// What the navigation does with the gyro bias estimated during alignment.
enum class GyroBiasMode {
  kRemove,  ///< subtract it from every gyro sample from t = 0 on
  kKeep,    ///< navigate on the raw gyro outputs (the estimate is only reported)
};
std::string_view to_string(GyroBiasMode m);  ///< "remove", "keep"
GyroBiasMode parse_gyro_bias_mode(std::string_view text, std::string_view field);

struct StrapdownOptions {
  /// L0, plumb-line latitude of the site, given by the user [rad]; |L0| < 90°.
  double latitude_rad = 45.0 * kDegToRad;
  /// Height of the site above the model sphere r0, also the computer's
  /// external altitude (3.21) [m]; in [−10 km, 100 km].
  double altitude_m = 0.0;
  /// Heading of the sensor x axis: angle from north to its horizontal
  /// projection, positive toward east (about down) [rad], given by the user
  /// as system 1's theodolite gives the platform azimuth; any finite value.
  double azimuth_rad = 0.0;
  /// Length of the alignment window before t = 0 [s]; > 0.
  double align_duration_s = 300.0;
  /// T, the test run [s]; > 0.
  double test_duration_s = 900.0;
  /// Navigation after the test run [s]; > 0.
  double nav_duration_s = 90.0 * kMinToS;
  /// τ: the output interval and the filter interval of Δf [s]; > 0 and ≤ T.
  double output_interval_s = 10.0;
  GyroBiasMode gyro_bias = GyroBiasMode::kRemove;
  double earth_rate_radps = kEarthRateRadps;  ///< ω_ie
  double gravity_mps2 = kGravityMps2;         ///< g of μ = g r0² (earth_model.h)
  double radius_m = kEarthRadiusM;            ///< r0

  /// Alignment, test run and navigation [s].
  double run_duration_s() const { return align_duration_s + test_duration_s + nav_duration_s; }
};

/// Checks every constraint above; throws InputError otherwise. Field names are the
/// command-line options of `insmc import-imu`.
void validate(const StrapdownOptions& options);

/// The stationary site on the model earth, in the earth-fixed frame e (= i at
/// t = 0) and the site's geographic frame n (north, east, down).
struct StationarySite {
  Vec3 position_e_m = Vec3::Zero();            ///< r^e, |r| = r0 + altitude
  Mat3 C_e_n = Mat3::Identity();               ///< n → e (= C_i_n(L0, 0), (3.3))
  Vec3 specific_force_n_mps2 = Vec3::Zero();   ///< f^n = −ω_ie × (ω_ie × r) − G(r), ≈ (0, 0, −g_s)
  Vec3 earth_rate_n_radps = Vec3::Zero();      ///< ω_ie^n = (ω cos L0, 0, −ω sin L0)
  double gravity_mps2 = 0.0;                   ///< g_s = |f| at the site
  double schuler_radps = 0.0;                  ///< sqrt(μ/R³), the computer's (3.21)
};
StationarySite stationary_site(const StrapdownOptions& options);

/// C_n_b (the report's C_b^n, body vectors into n) for the 3-2-1 Euler
/// angles of the body: heading ψ about down, then pitch θ about the new y,
/// then roll φ about the new x [rad] (the standard aerospace sequence,
/// C_n_b = R_z(ψ) R_y(θ) R_x(φ)).
Mat3 C_n_b_from_euler(double roll_rad, double pitch_rad, double heading_rad);

/// The alignment of one run, from the samples of its window.
struct StrapdownAlignment {
  Mat3 C_ap_b = Mat3::Identity();      ///< body attitude at t = 0 in a' (= n at t = 0)
  double roll_rad = 0.0;               ///< φ from leveling
  double pitch_rad = 0.0;              ///< θ from leveling
  Vec3 mean_accel_b_mps2 = Vec3::Zero();  ///< mean f^b over the window
  Vec3 mean_gyro_b_radps = Vec3::Zero();  ///< mean ω_ib^b over the window
  /// Estimated gyro bias: mean_gyro − C_n^b ω_ie^n [rad/s].
  Vec3 gyro_bias_b_radps = Vec3::Zero();
  std::size_t samples = 0;             ///< samples in the window
};

/// Levels the body from `mean_accel_b_mps2` and sets the heading to
/// `options.azimuth_rad`: C_n_b with C_n_b f̄^b pointing up (−z of n). Throws
/// InputError (naming `source`) when |f̄| is outside [0.5 g, 2 g] (not a
/// stationary IMU, or wrong accelerometer unit or columns), when |ω̄| exceeds
/// 0.5 rad/s (motion, or wrong gyro unit), or when the sensor x axis lies
/// within 10° of the vertical (heading undefined).
StrapdownAlignment align_stationary(const Vec3& mean_accel_b_mps2, const Vec3& mean_gyro_b_radps,
                                    std::size_t samples, const StrapdownOptions& options,
                                    const StationarySite& site, std::string_view source);

/// One run: alignment, test run and navigation, sampled at the output times.
struct StrapdownRun {
  StrapdownAlignment alignment;
  /// Time of the switch to navigation (t = 0) on the file's clock [s].
  double switch_time_s = 0.0;
  std::vector<double> t_s;                  ///< τ, 2τ, …, T + nav [s]
  /// Δf^a over (t − τ, t] in a' [m/s²]; NaN where t < τ.
  std::vector<Vec3> accel_error_ap_mps2;
  std::vector<Vec3> position_error_ap_m;    ///< δr^{a'} = r_c − r [m]
};

/// How many consecutive runs of run_duration_s() the samples hold (0 if none).
int runs_available(const ImuSamples& samples, const StrapdownOptions& options);

/// The run whose alignment window starts at `start_s` on the file's clock:
/// t = 0 is the first sample time ≥ start_s + align_duration_s. Throws
/// InputError when the samples do not cover the run (naming the source, what
/// they cover and what the run needs).
StrapdownRun run_strapdown(const ImuSamples& samples, double start_s, const StrapdownOptions& options);

}  // namespace insmc
