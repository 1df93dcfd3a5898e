#pragma once
/// Values with units on the command line and in INI files ("15min", "10meru",
/// "1mg", "0.3mps", "100m", "1mrad", "20arcsec", "45deg", "50ppm", and the
/// sensor-spec random walks "0.005degprth" (deg/√h), "0.03mpsprth"), parsed by
/// one function into SI; the number and the unit are each read whole
/// (split_quantity), so that no part of one is taken for the other. A dimensional value without a unit is refused with
/// the list of accepted units; dimensionless values are bare (or "ppm").
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace insmc {

enum class Dimension {
  kDimensionless,   ///< bare number, or ppm
  kLength,          ///< m
  kTime,            ///< s
  kAngle,           ///< rad
  kAngularRate,     ///< rad/s
  kVelocity,        ///< m/s
  kAcceleration,    ///< m/s²
  kAngleRandomWalk,     ///< rad/√s (a gyro's white rate noise; deg/√h on data sheets)
  kVelocityRandomWalk,  ///< m/s/√s (an accelerometer's white noise; m/s/√h on data sheets)
};

/// Name of the SI unit used in file columns and JSON keys ("m", "s", "rad",
/// "radps", "mps", "mps2", "radprts", "mpsprts", "" for dimensionless).
std::string_view si_suffix(Dimension d);

/// The longest value text parse_quantity reads: a number with its unit is
/// ~30 bytes; 256 leaves room for any spelling of one.
inline constexpr std::size_t kMaxQuantityTextBytes = 256;

/// A value's text split into its number and its unit, each read whole: the
/// number is decimal (an optional sign, digits with an optional point, an
/// optional exponent: "5", "-0.5", ".5", "1e3"; no blank before it, no
/// hexadecimal, no inf or nan), blanks may follow it, and the unit is the
/// rest of the text, empty when there is none. `number` is infinite when
/// the magnitude is beyond a double's range.
struct QuantityText {
  double number = 0.0;
  std::string_view unit;
};
/// None when the text does not start with such a number.
std::optional<QuantityText> split_quantity(std::string_view text);

/// The SI factor of a unit of `dimension` named whole (a name of
/// accepted_units or one of its usual spellings, e.g. "min", "deg/h",
/// "m/s/√h"); none for anything else: nothing of a unit is read as a number.
std::optional<double> unit_factor(std::string_view unit, Dimension dimension);

/// Parses `text` as a number followed by a unit of `dimension`; returns SI.
/// Throws InputError naming `field` on a missing or wrong unit, a malformed
/// number, a non-finite value (also after conversion to SI), or a text
/// longer than kMaxQuantityTextBytes; the text is echoed escaped and cut
/// (lib/common/input_text.h).
double parse_quantity(std::string_view text, Dimension dimension, std::string_view field);

/// Formats an SI value in the most natural accepted unit for messages,
/// INI round trips and run.json (e.g. "10meru", "1mg", "900s").
std::string format_quantity(double value_si, Dimension dimension);

}  // namespace insmc
