#pragma once
/// Strict, locale-independent parsing of numbers in record files: the whole
/// text must be one decimal number ("45", "45.0", "45.000", "4.5e1", "-.5",
/// "+3"); NaN and infinities are refused. Exact: the writer's fmt "{}"
/// output parses back to the same bits.
#include <cstdint>
#include <string_view>

namespace insmc::records_detail {

enum class NumberStatus {
  kOk,
  kNotANumber,   ///< empty, or not a decimal number as a whole
  kNonFinite,    ///< nan, inf, infinity (any case, any sign)
  kOutOfRange,   ///< magnitude beyond the double range
  kNotInteger,   ///< a finite number that is not an integer in int64 range
};

/// Parses a double; `value` is written only on kOk.
NumberStatus parse_double(std::string_view text, double& value);
/// Parses an int64, also accepting an integral value written as a decimal
/// number ("3.0", "3e0"); `value` is written only on kOk.
NumberStatus parse_int64(std::string_view text, std::int64_t& value);

/// Text for an error message about `status` ("not a number", ...).
std::string_view describe(NumberStatus status);

}  // namespace insmc::records_detail
