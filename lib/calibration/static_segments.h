#pragma once
/// The still intervals of a recording in which the sensor was turned by hand
/// between attitudes (a multi-position calibration): windows whose
/// variance, on every gyro and accelerometer axis, stays near the quietest
/// windows' (sensor noise), and whose gyro means stay near the median
/// window's (a steady turn has noise-level variance), joined into segments.
/// Needs most of the recording still (the medians are the still windows').
#include <cstddef>
#include <vector>

#include "lib/imu/imu_samples.h"

namespace insmc::calibration {

/// Fewest samples per window: with fewer the windows' variances scatter so
/// widely (χ²₁₉/19 < 2.9 at 0.9999) that still windows would pass for turns.
inline constexpr std::size_t kMinWindowSamples = 20;

/// Samples [begin, end) of one still interval.
struct StaticSegment {
  std::size_t begin = 0, end = 0;
};

struct StaticDetection {
  /// Window length; the variance test runs on consecutive windows of this
  /// length (at least kMinWindowSamples each).
  double window_s = 0.5;
  /// A window is still when each axis's variance is at most this factor
  /// times the axis's reference: the 20th percentile of all windows'
  /// variances (noise, as long as a fifth of the windows are still). A
  /// hand turn raises the variance by 10³–10⁴; white noise over 50 samples
  /// keeps it within 2× of the reference (χ²₄₉/49 < 1.9 at 0.9999).
  double variance_factor = 10.0;
  /// A segment keeps this long at least, after one window is cut from each
  /// end (where the turn begins or ends within the window).
  double min_duration_s = 2.0;
};

/// The still segments of `samples`, in time order. At most one per window.
std::vector<StaticSegment> find_static_segments(const ImuSamples& samples, const StaticDetection& options);

}  // namespace insmc::calibration
