#pragma once
/// Colours and numbers as the gnuplot figures write them.
#include <cmath>
#include <iterator>
#include <string>

#include <fmt/format.h>

namespace insmc::mc {

/// Colour-blind-safe palette (Okabe and Ito), by index, repeating.
inline const char* palette_colour(int index) {
  static constexpr const char* kPalette[] = {"#0072B2", "#D55E00", "#009E73", "#CC79A7",
                                             "#E69F00", "#56B4E9", "#000000", "#F0E442"};
  constexpr int n = static_cast<int>(std::size(kPalette));
  return kPalette[((index % n) + n) % n];
}

/// A data value: 9 significant digits, NaN (gnuplot's missing) when not finite.
inline std::string plot_number(double v) { return std::isfinite(v) ? fmt::format("{:.9g}", v) : "NaN"; }

}  // namespace insmc::mc
