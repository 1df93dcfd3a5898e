#include "montecarlo/report/interval_format.h"

#include <fmt/format.h>

#include <cmath>

namespace insmc::mc {
namespace {

// Beyond these places fixed notation gets long runs of zeros.
constexpr int kFixedPlaceMin = -6, kFixedPlaceMax = 6;
// A double carries about 16 significant decimal figures.
constexpr int kMaxFigures = 16;

std::string non_finite(double x) {
  if (std::isnan(x)) return "nan";
  return x > 0 ? "inf" : "-inf";
}

int decade(double x) { return static_cast<int>(std::floor(std::log10(std::fabs(x)))); }

}  // namespace

std::optional<int> interval_place(double half_width) {
  if (!std::isfinite(half_width) || half_width <= 0) return std::nullopt;
  int place = decade(half_width) - 1;
  // log10 may land a hair off an exact power of ten, and rounding to two
  // figures may carry into a third (99.7 -> 100): settle on the place whose
  // rounded half-width has exactly two figures.
  for (int i = 0; i < 2; ++i) {
    const double r = std::round(half_width / std::pow(10.0, place));
    if (r >= 100) {
      ++place;
    } else if (r < 10) {
      --place;
    } else {
      break;
    }
  }
  return place;
}

std::string format_at_place(double x, int place) {
  if (!std::isfinite(x)) return non_finite(x);
  if (x != 0) place = std::max(place, decade(x) - kMaxFigures + 1);
  const double step = std::pow(10.0, place);
  double rounded = std::round(x / step) * step;
  if (rounded == 0) rounded = 0;  // no "-0"
  if (place >= kFixedPlaceMin && place <= kFixedPlaceMax && std::fabs(rounded) < 1e15)
    return place >= 0 ? fmt::format("{:.0f}", rounded) : fmt::format("{:.{}f}", rounded, -place);
  if (rounded == 0) return "0";
  return fmt::format("{:.{}e}", rounded, std::max(0, decade(rounded) - place));
}

std::string format_significant(double x, int digits) {
  if (!std::isfinite(x)) return non_finite(x);
  if (x == 0) return "0";
  return format_at_place(x, decade(x) - digits + 1);
}

std::string format_with_interval(double x, double half_width) {
  if (std::isnan(x)) return "nan";
  const double h = std::fabs(half_width);
  const std::optional<int> place = interval_place(h);
  if (!place) {
    if (std::isfinite(h)) return fmt::format("{} ± 0", format_significant(x, 6));
    return fmt::format("{} ± {}", format_significant(x, 2), non_finite(h));
  }
  return fmt::format("{} ± {}", format_at_place(x, *place), format_at_place(h, *place));
}

}  // namespace insmc::mc
