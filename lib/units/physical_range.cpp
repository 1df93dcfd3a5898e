#include "lib/units/physical_range.h"

#include <cmath>
#include <fmt/format.h>

#include "lib/common/input_error.h"
#include "lib/units/units.h"

namespace insmc {

namespace {

/// "[0, 1mps]" or "(0s, 2h]": the range in the units format_quantity picks.
std::string describe(const PhysicalRange& range, Dimension dimension) {
  return fmt::format("{}{}, {}]", range.min_open ? "(" : "[", format_quantity(range.min_si, dimension),
                     format_quantity(range.max_si, dimension));
}

}  // namespace

void require_in_range(std::string_view field, double value_si, Dimension dimension, const PhysicalRange& range,
                      std::string_view why) {
  if (std::isfinite(value_si) && range.contains(value_si)) return;
  std::string allowed = "must lie in " + describe(range, dimension);
  if (!why.empty()) allowed += fmt::format(" ({})", why);
  // A bare number in its shortest exact form: 0.9999999999999999 must not read as 1.
  const std::string value =
      dimension == Dimension::kDimensionless ? fmt::format("{}", value_si) : format_quantity(value_si, dimension);
  throw InputError(std::string(field), value, allowed);
}

double magnitude_limit(Dimension dimension) {
  switch (dimension) {
    case Dimension::kAngle: return 100 * kMradToRad;
    case Dimension::kAngularRate: return 1e4 * kMeruToRadps;
    case Dimension::kAcceleration: return 100 * kMgToMps2;
    case Dimension::kVelocity: return 10.0;
    case Dimension::kLength: return 1e6;
    case Dimension::kTime: return 48 * 3600.0;
    case Dimension::kDimensionless: return 0.1;
    // Random walks: 1,000 deg/√h (the noisiest MEMS gyros are near 10) and
    // 60 m/s/√h (MEMS accelerometers are near 0.1).
    case Dimension::kAngleRandomWalk: return 1000 * kDegToRad / 60;
    case Dimension::kVelocityRandomWalk: return 1.0;
  }
  return 0.0;
}

PhysicalRange non_negative_range(Dimension dimension) { return {0.0, magnitude_limit(dimension)}; }

}  // namespace insmc
