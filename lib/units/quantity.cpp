#include "lib/units/quantity.h"
#include "lib/units/quantity_display.h"

#include <charconv>
#include <cmath>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <span>
#include <string>

#include "lib/common/input_error.h"
#include "lib/common/input_text.h"
#include "lib/units/units.h"

namespace insmc {
namespace {

struct UnitFactor {
  const char* name;
  double to_si;
};

// The first entry of each table is the unit format_quantity prefers.
constexpr UnitFactor kLengthUnits[] = {{"m", 1.0}, {"ft", kFtToM}, {"km", 1e3}, {"nmi", kNmiToM}};
constexpr UnitFactor kTimeUnits[] = {{"s", 1.0}, {"min", kMinToS}, {"h", kHourToS}, {"ms", 1e-3}};
constexpr UnitFactor kAngleUnits[] = {{"rad", 1.0},         {"mrad", kMradToRad},
                                      {"urad", kUradToRad}, {"deg", kDegToRad},
                                      {"arcmin", kArcminToRad}, {"arcsec", kArcsecToRad}};
constexpr UnitFactor kRateUnits[] = {{"radps", 1.0},
                                     {"meru", kMeruToRadps},
                                     {"degph", kDegphToRadps},
                                     {"degps", kDegToRad},
                                     {"mradps", 1e-3}};
constexpr UnitFactor kVelocityUnits[] = {{"mps", 1.0}, {"ftps", kFtpsToMps}, {"mmps", 1e-3}};
constexpr UnitFactor kAccelerationUnits[] = {
    {"mps2", 1.0}, {"mg", kMgToMps2}, {"ug", kUgToMps2}, {"g", kGravityMps2}, {"ftps2", kFtToM}};
// "prth": per root hour (1/√h = 1/60 · 1/√s), "prts": per root second.
constexpr UnitFactor kAngleWalkUnits[] = {{"radprts", 1.0}, {"degprth", kDegToRad / 60}, {"degprts", kDegToRad}};
constexpr UnitFactor kVelocityWalkUnits[] = {{"mpsprts", 1.0}, {"mpsprth", 1.0 / 60}, {"ftpsprth", kFtToM / 60}};
constexpr UnitFactor kDimensionlessUnits[] = {{"", 1.0}, {"ppm", kPpmToUnit}};

/// Spellings engineers type for the units above (the paper's, data sheets'
/// and plain SI), each to the name in the tables.
struct UnitSpelling {
  const char* typed;
  const char* name;
};
constexpr UnitSpelling kSpellings[] = {
    {"deg/h", "degph"},    {"deg/hr", "degph"},     {"°/h", "degph"},           {"°/hr", "degph"},
    {"dph", "degph"},      {"deg/s", "degps"},      {"°/s", "degps"},           {"mrad/s", "mradps"},
    {"rad/s", "radps"},    {"µg", "ug"},            {"μg", "ug"},               {"m/s", "mps"},
    {"ft/s", "ftps"},      {"fps", "ftps"},         {"mm/s", "mmps"},           {"m/s2", "mps2"},
    {"m/s^2", "mps2"},     {"m/s²", "mps2"},        {"ft/s2", "ftps2"},         {"ft/s^2", "ftps2"},
    {"ft/s²", "ftps2"},    {"NM", "nmi"},           {"nm", "nmi"},              {"n.mi.", "nmi"},
    {"µrad", "urad"},      {"μrad", "urad"},        {"°", "deg"},               {"hr", "h"},
    {"sec", "s"},          {"deg/sqrt(h)", "degprth"}, {"deg/√h", "degprth"},   {"deg/rt-h", "degprth"},
    {"m/s/sqrt(h)", "mpsprth"}, {"m/s/√h", "mpsprth"}, {"ft/s/sqrt(h)", "ftpsprth"}, {"ft/s/√h", "ftpsprth"},
};

std::string_view unit_name_of(std::string_view typed) {
  for (const UnitSpelling& s : kSpellings)
    if (typed == s.typed) return s.name;
  return typed;
}

std::span<const UnitFactor> units_of(Dimension d) {
  switch (d) {
    case Dimension::kLength: return kLengthUnits;
    case Dimension::kTime: return kTimeUnits;
    case Dimension::kAngle: return kAngleUnits;
    case Dimension::kAngularRate: return kRateUnits;
    case Dimension::kVelocity: return kVelocityUnits;
    case Dimension::kAcceleration: return kAccelerationUnits;
    case Dimension::kAngleRandomWalk: return kAngleWalkUnits;
    case Dimension::kVelocityRandomWalk: return kVelocityWalkUnits;
    case Dimension::kDimensionless: return kDimensionlessUnits;
  }
  return kDimensionlessUnits;
}

/// The unit spellings accepted for a dimension, e.g. {"m","ft","km","nmi"}.
std::vector<std::string> accepted_units(Dimension d) {
  std::vector<std::string> out;
  for (const auto& u : units_of(d)) out.emplace_back(u.name);
  return out;
}

std::string accepted_list(Dimension d) {
  if (d == Dimension::kDimensionless) return "a bare number (or NUMBERppm)";
  std::vector<std::string> names = accepted_units(d), spellings;
  for (const UnitSpelling& s : kSpellings)
    for (const auto& u : units_of(d))
      if (std::string_view(s.name) == u.name) spellings.emplace_back(s.typed);
  return fmt::format("a number with one of the units {}{}", fmt::join(names, ", "),
                     spellings.empty() ? "" : fmt::format(" (also {})", fmt::join(spellings, ", ")));
}

}  // namespace

std::string_view si_suffix(Dimension d) {
  switch (d) {
    case Dimension::kLength: return "m";
    case Dimension::kTime: return "s";
    case Dimension::kAngle: return "rad";
    case Dimension::kAngularRate: return "radps";
    case Dimension::kVelocity: return "mps";
    case Dimension::kAcceleration: return "mps2";
    case Dimension::kAngleRandomWalk: return "radprts";
    case Dimension::kVelocityRandomWalk: return "mpsprts";
    case Dimension::kDimensionless: return "";
  }
  return "";
}

std::optional<QuantityText> split_quantity(std::string_view text) {
  const auto digit = [&](std::size_t i) { return i < text.size() && text[i] >= '0' && text[i] <= '9'; };
  std::size_t i = 0;
  if (i < text.size() && (text[i] == '+' || text[i] == '-')) ++i;
  const std::size_t first_digit = i;
  std::size_t digits = 0;
  for (; digit(i); ++i) ++digits;
  if (i < text.size() && text[i] == '.')
    for (++i; digit(i); ++i) ++digits;
  if (digits == 0) return std::nullopt;  // "", "-", ".", "e3", "x5"
  // An exponent only when digits follow it ("5e3"); "5e" is 5 with the unit "e".
  if (i < text.size() && (text[i] == 'e' || text[i] == 'E')) {
    std::size_t j = i + 1;
    if (j < text.size() && (text[j] == '+' || text[j] == '-')) ++j;
    if (digit(j)) {
      for (i = j; digit(i); ++i) {
      }
    }
  }
  // from_chars reads no leading '+'; the sign is applied here.
  QuantityText out;
  const std::string_view body = text.substr(first_digit, i - first_digit);
  const auto [ptr, ec] = std::from_chars(body.data(), body.data() + body.size(), out.number, std::chars_format::general);
  if (ec == std::errc::result_out_of_range) {
    out.number = HUGE_VAL;  // beyond a double (or below its smallest): refused as not finite
  } else if (ec != std::errc() || ptr != body.data() + body.size()) {
    return std::nullopt;
  }
  if (text[0] == '-') out.number = -out.number;
  std::size_t unit_start = i;
  while (unit_start < text.size() && text[unit_start] == ' ') ++unit_start;
  out.unit = text.substr(unit_start);
  return out;
}

std::optional<double> unit_factor(std::string_view unit, Dimension dimension) {
  const std::string_view name = unit_name_of(unit);
  for (const auto& u : units_of(dimension))
    if (name == u.name) return u.to_si;
  return std::nullopt;
}

double parse_quantity(std::string_view text, Dimension dimension, std::string_view field) {
  const std::string allowed = accepted_list(dimension);
  if (text.size() > kMaxQuantityTextBytes)
    throw InputError(std::string(field), echo_input(text),
                     fmt::format("{} bytes: a value holds at most {} bytes; expected {}", text.size(),
                                 kMaxQuantityTextBytes, allowed));
  const std::string shown = echo_input(text);
  if (text.empty()) throw InputError(std::string(field), "''", "expected " + allowed);
  // A NUL byte would end the text for C functions downstream: no value holds one.
  if (text.find('\0') != std::string_view::npos)
    throw InputError(std::string(field), shown, "not a number; expected " + allowed);
  const std::optional<QuantityText> q = split_quantity(text);
  if (!q) throw InputError(std::string(field), shown, "not a number; expected " + allowed);
  if (!std::isfinite(q->number)) throw InputError(std::string(field), shown, "must be finite; expected " + allowed);
  if (const std::optional<double> factor = unit_factor(q->unit, dimension)) {
    const double si = q->number * *factor;
    if (!std::isfinite(si)) throw InputError(std::string(field), shown, "must be finite; expected " + allowed);
    return si;
  }
  if (q->unit.empty()) throw InputError(std::string(field), shown, "a unit is required; expected " + allowed);
  throw InputError(std::string(field), shown, "unknown unit '" + echo_input(q->unit) + "'; expected " + allowed);
}

std::string format_quantity_rounded(double value_si, Dimension dimension, int significant_digits) {
  // Prefer the paper's unit where one is natural for the quantity.
  const UnitFactor* chosen = &units_of(dimension)[0];
  for (const auto& u : units_of(dimension)) {
    const std::string_view name = u.name;
    if (name == "meru" || name == "mg" || name == "mrad" || name == "ppm" || name == "degprth" || name == "mpsprth")
      chosen = &u;
  }
  if (dimension == Dimension::kDimensionless) chosen = &units_of(dimension)[0];
  return fmt::format("{:.{}g}{}", value_si / chosen->to_si, significant_digits, chosen->name);
}

std::string format_quantity(double value_si, Dimension dimension) {
  return format_quantity_rounded(value_si, dimension, 12);
}

}  // namespace insmc
