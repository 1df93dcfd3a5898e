#include "lib/records/number_text.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <string>
#include <system_error>

namespace insmc::records_detail {
namespace {

bool iequals(std::string_view a, std::string_view b) {
  return a.size() == b.size() &&
         std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
           return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
         });
}

bool spells_non_finite(std::string_view text) {
  if (!text.empty() && (text.front() == '+' || text.front() == '-')) text.remove_prefix(1);
  return iequals(text, "nan") || iequals(text, "inf") || iequals(text, "infinity") ||
         (text.size() >= 5 && iequals(text.substr(0, 4), "nan(") && text.back() == ')');
}

}  // namespace

NumberStatus parse_double(std::string_view text, double& value) {
  if (text.empty()) return NumberStatus::kNotANumber;
  if (spells_non_finite(text)) return NumberStatus::kNonFinite;
  std::string_view body = text;
  // std::from_chars takes no leading '+'; other software writes one.
  if (body.front() == '+') {
    body.remove_prefix(1);
    if (body.empty() || body.front() == '+' || body.front() == '-') return NumberStatus::kNotANumber;
  }
  double parsed = 0.0;
  const char* const end = body.data() + body.size();
  const auto [ptr, ec] = std::from_chars(body.data(), end, parsed, std::chars_format::general);
  if (ec == std::errc::result_out_of_range) return NumberStatus::kOutOfRange;
  if (ec != std::errc() || ptr != end) return NumberStatus::kNotANumber;
  if (!std::isfinite(parsed)) return NumberStatus::kNonFinite;
  value = parsed;
  return NumberStatus::kOk;
}

NumberStatus parse_int64(std::string_view text, std::int64_t& value) {
  std::string_view body = text;
  if (!body.empty() && body.front() == '+') body.remove_prefix(1);
  if (!body.empty() && body.front() != '+' && !(text.front() == '+' && body.front() == '-')) {
    std::int64_t parsed = 0;
    const char* const end = body.data() + body.size();
    const auto [ptr, ec] = std::from_chars(body.data(), end, parsed);
    if (ec == std::errc() && ptr == end) {
      value = parsed;
      return NumberStatus::kOk;
    }
  }
  double d = 0.0;
  const NumberStatus s = parse_double(text, d);
  if (s != NumberStatus::kOk) return s;
  // 2^63 is exact in double; the int64 range is [-2^63, 2^63).
  constexpr double kTwo63 = 9223372036854775808.0;
  if (d != std::trunc(d) || d < -kTwo63 || d >= kTwo63) return NumberStatus::kNotInteger;
  value = static_cast<std::int64_t>(d);
  return NumberStatus::kOk;
}

std::string_view describe(NumberStatus status) {
  switch (status) {
    case NumberStatus::kOk: return "a number";
    case NumberStatus::kNotANumber: return "not a number";
    case NumberStatus::kNonFinite: return "not finite (NaN and infinities are not allowed)";
    case NumberStatus::kOutOfRange: return "out of the range of a double";
    case NumberStatus::kNotInteger: return "not an integer";
  }
  return "not a number";
}

}  // namespace insmc::records_detail
