#pragma once
/// Agreement of a computed value with a printed one in significant digits:
/// the log relative error LRE = −log10(|computed − printed| / |printed|), as
/// Ceres scores its NIST problems (examples/nist.cc, ComputeLRE). A printed
/// value with d significant digits is reproduced to all its digits when the
/// LRE is at least about d (rounding alone can cost up to one digit).
#include <algorithm>
#include <cmath>
#include <optional>

namespace insmc::tables {

/// Cap on the LRE: agreement beyond this many digits is exact for a table.
inline constexpr double kMaxLre = 15.0;

/// LRE of `computed` against `printed`; absent when `printed` is 0 (no
/// relative error exists); kMaxLre when they are equal.
inline std::optional<double> log_relative_error(double computed, double printed) {
  if (printed == 0.0) return std::nullopt;
  const double rel = std::abs(computed - printed) / std::abs(printed);
  if (rel == 0.0) return kMaxLre;
  return std::clamp(-std::log10(rel), 0.0, kMaxLre);
}

}  // namespace insmc::tables
