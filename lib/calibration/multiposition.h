#pragma once
/// Multi-position calibration of a strapdown IMU without external equipment
/// (the method of Tedaldi, Pretto and Menegatti, ICRA 2014, on which IMU-TK
/// is built): the sensor rests in many attitudes, turned by hand between
/// them. Gravity's magnitude is the only reference.
///
/// Accelerometers (equation numbers of docs/noise.md §6):
///   f = (I + M_a)(a − b_a),   M_a = [s_x α_xy α_xz; 0 s_y α_yz; 0 0 s_z]      (C.1)
/// fitted so that every still attitude's mean has ‖f_i‖ = g                      (C.2)
/// (9 parameters: bias, scale-factor error, non-orthogonality; the body frame
/// is the accelerometer triad's own: z along its z axis, y in its y–z plane).
///
/// Gyros, in two steps:
///   ω̄_i = b_g + G f_i   on the still attitudes' means (bias, g-sensitivity)     (C.3)
///   ω = (I + M_g)(ω_raw − b_g − G f)   integrated through each turn, so that
///   the gravity direction of attitude i, carried through the turn, lands on
///   that of attitude i+1                                                       (C.4)
/// (M_g: 3 scale-factor errors on its diagonal, 6 misalignments of the gyro
/// axes against the accelerometer frame off it).
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

#include "lib/calibration/least_squares.h"
#include "lib/calibration/static_segments.h"
#include "lib/frames/frames.h"
#include "lib/imu/imu_samples.h"

namespace insmc::calibration {

/// What a calibrated quantity is (its unit at the report's edge).
enum class ParameterKind { kAccelBias, kGyroBias, kScaleFactor, kMisalignment, kGSensitivity };

struct CalibratedParameter {
  std::string name;       ///< e.g. "accel_bias_x", "gyro_scale_factor_y", "g_sensitivity_xz"
  ParameterKind kind;
  double value_si = 0;    ///< m/s², rad/s, dimensionless, rad, rad/s per m/s²
  double sigma_si = 0;    ///< standard error (+inf: not determined)
  double lo_si = 0, hi_si = 0;  ///< the interval at the options' confidence
  double vif = 1;         ///< variance inflation (least_squares.h)
  bool separable() const { return vif <= kMaxSeparableVif && std::isfinite(sigma_si); }
};

/// One fit's parameters and its residual scatter.
struct FitSummary {
  std::vector<CalibratedParameter> parameters;
  double residual_rms_si = 0;  ///< of (C.2) [m/s²], (C.3) [rad/s] or (C.4) [rad]
  int residuals = 0;
  bool fitted = false;
  std::string why_not;         ///< when not fitted
};

struct MultipositionOptions {
  StaticDetection detection;
  double gravity_mps2 = 9.80665;  ///< the site's gravity magnitude (the only reference)
  double confidence = 0.95;
  /// Still attitudes whose mean specific-force directions are within this
  /// angle count as one orientation.
  double same_orientation_rad = 5.0 * 3.14159265358979323846 / 180.0;
};

struct MultipositionCalibration {
  std::vector<StaticSegment> segments;
  std::vector<Vec3> segment_accel_mps2;  ///< each segment's raw mean accelerometer output
  std::vector<Vec3> segment_gyro_radps;  ///< and gyro output
  std::size_t orientations = 0;          ///< distinct ones (options' angle)
  FitSummary accel;                      ///< (C.1)-(C.2)
  FitSummary gyro_static;                ///< (C.3), one fit per gyro axis
  std::vector<double> g_sensitivity_p;   ///< per gyro axis: F-test of G's row = 0 in (C.3)
  FitSummary gyro_turns;                 ///< (C.4)
};

/// Fewest still attitudes for the accelerometer fit (9 parameters and a
/// residual scatter worth estimating).
inline constexpr std::size_t kMinCalibrationSegments = 12;
/// The least spread of the attitudes' gravity directions, and of the
/// turns' rotation axes: the smallest eigenvalue of the mean of u uᵀ over
/// their unit vectors (1/3 for an even spread; 0.02 is about a direction
/// 8° out of a plane on average). The project's choice: below it the
/// unseen axis's parameters are fitted from noise.
inline constexpr double kMinDirectionSpread = 0.02;
/// Longest motion between two still attitudes that counts as a turn in
/// (C.4); a longer one (the sensor carried about) is left out.
inline constexpr double kMaxTurnS = 30.0;
/// Largest RMS error of the gravity direction after the turns that (C.4)
/// accepts; beyond it the gyro data do not follow the model (a wrong unit
/// or column, or turns the samples cannot follow). The Xsens set: 1.7 mrad.
inline constexpr double kMaxTurnResidualRad = 0.02;

/// Calibrates from one recording. Fits that the data cannot carry (too few
/// segments or orientations) are left unfitted with the reason.
MultipositionCalibration calibrate_multiposition(const ImuSamples& samples, const MultipositionOptions& options);

/// The number of distinct directions among the vectors `f` (mean specific
/// forces): a direction within `same_rad` of one already counted is the same.
/// Zero vectors have none.
std::size_t distinct_directions(const std::vector<Vec3>& f, double same_rad);

}  // namespace insmc::calibration
