#pragma once
/// The unit of the position columns (--units): metres (SI), the paper's
/// feet or nautical miles. Column names carry it (`rms_m`, `rms_ft`,
/// `rms_nmi`); SI inside, converted only when written.
#include <string>

#include "lib/units/units.h"

namespace insmc::mc {

enum class LengthUnit { kMetre, kFoot, kNauticalMile };

/// Printed value = factor · metres.
inline double length_factor(LengthUnit u) {
  switch (u) {
    case LengthUnit::kFoot: return 1.0 / kFtToM;
    case LengthUnit::kNauticalMile: return 1.0 / kNmiToM;
    case LengthUnit::kMetre: break;
  }
  return 1.0;
}

inline std::string length_suffix(LengthUnit u) {
  switch (u) {
    case LengthUnit::kFoot: return "ft";
    case LengthUnit::kNauticalMile: return "nmi";
    case LengthUnit::kMetre: break;
  }
  return "m";
}

}  // namespace insmc::mc
