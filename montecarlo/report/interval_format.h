#pragma once
/// Numbers for people, printed to the precision their confidence interval
/// supports: a Monte Carlo RMS of 28825.3 m whose interval half-width is
/// 480 m is printed "28830 ± 480". Six significant figures beside a
/// two-figure interval claim a precision the samples do not have. Machine
/// outputs (CSV, JSON) keep full precision (format_number in csv.h).
#include <optional>
#include <string>

namespace insmc::mc {

/// The decimal place (10^place) of the second significant figure of
/// `half_width` once rounded to two figures: 480.3 -> 1 (tens), 0.0012 -> -4,
/// 99.7 -> 1 (it rounds to 100). None for 0, negative, NaN or infinite
/// half-widths: they give no precision to round to.
std::optional<int> interval_place(double half_width);

/// `x` rounded to a multiple of 10^place: "28830" (place 1), "0.0012"
/// (place -4). Fixed notation for places in [-6, 6] (lengths in metres or
/// feet from micrometres to megametres); scientific beyond, with the digits
/// down to that place ("2.500e+20" for place 17). Never more than 16
/// significant figures (a double holds no more); "nan", "inf", "-inf".
std::string format_at_place(double x, int place);

/// `x` to `digits` significant figures in the notation of format_at_place
/// (12255.3582 -> "12255" for 5 digits); for values without an interval.
std::string format_significant(double x, int digits);

/// "VALUE ± HALF": the half-width to two significant figures and the value
/// to the same decimal place ("28830 ± 480", "0.0213 ± 0.0012",
/// "0 ± 4800" for 3.2 ± 4800). A zero half-width (every sample alike) keeps
/// six significant figures: "1234.57 ± 0". An infinite or NaN one (a median
/// of two samples: its interval reaches beyond them) bounds nothing, and the
/// value keeps two figures, as beside the widest interval: "1200 ± inf".
/// A NaN value is "nan" whatever the interval.
std::string format_with_interval(double x, double half_width);

}  // namespace insmc::mc
