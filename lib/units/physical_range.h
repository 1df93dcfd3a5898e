#pragma once
/// Physical ranges of input values. Every value a user can give (an option,
/// an INI key, an uncertainty bound, an effect parameter) has a range stated
/// once, next to where the value is defined; a value outside it is refused
/// with exit 2 before any work, naming the field, the value and the range.
/// The ranges are wide enough for any inertial system the linearized error
/// model of the report describes (navigation grade down to tactical grade)
/// and narrow enough that no computation overflows or runs unbounded.
#include <string>
#include <string_view>

#include "lib/units/quantity.h"

namespace insmc {

struct PhysicalRange {
  double min_si;          ///< lowest allowed value
  double max_si;          ///< highest allowed value
  bool min_open = false;  ///< min itself not allowed (e.g. a time that must be > 0)
  bool contains(double v) const { return (min_open ? v > min_si : v >= min_si) && v <= max_si; }
};

/// A position error or a limit on one: beyond the earth's circumference it
/// means nothing, and a larger number is a typo (1e306 nmi once became inf m).
inline constexpr PhysicalRange kPositionLimitRange{0.0, 4.0e7, true};

/// A site's gravity magnitude [m/s²]: from the equator at sea level (9.780)
/// to the poles (9.832), with room for altitude and local anomalies.
inline constexpr PhysicalRange kSiteGravityRange{9.7, 9.9};

/// Throws InputError(field, value, "must lie in RANGE" + why) unless `value_si`
/// is finite and inside `range`. `why` (optional) says where the limit comes
/// from, e.g. "the small-angle model of (3.24)".
void require_in_range(std::string_view field, double value_si, Dimension dimension, const PhysicalRange& range,
                      std::string_view why = {});

/// The largest magnitude of an error source of each dimension that the
/// linearized model still describes: the ceiling for uncertainty bounds and
/// effect magnitudes that do not state a tighter one.
///   angle          100 mrad (≈ 6°: sin θ ≈ θ within 0.2 %)
///   angular rate   10,000 meru (≈ 150 °/h: a tactical gyro's drift; the
///                  small-angle model breaks within minutes beyond)
///   acceleration   100 mg (far beyond any navigation accelerometer's bias)
///   velocity       10 m/s (initial-velocity errors of a vehicle at rest)
///   length         1000 km (a gravity-model offset the diagnosis fits)
///   time           48 h (the longest run any command simulates or reads)
///   dimensionless  0.1 (scale factors, 1e5 ppm)
double magnitude_limit(Dimension dimension);

/// [0, magnitude_limit(dimension)]
PhysicalRange non_negative_range(Dimension dimension);

}  // namespace insmc
