#pragma once
/// The compensation schemes of chapter 5 (DESIGN.md §1 item 5), each with
/// the clock its results are reported on (item 6).
#include <string_view>
#include <vector>

namespace insmc {

enum class Scheme { kNone };

/// "none", "5.1.1", ... — the one spelling used in options and files.
std::string_view to_string(Scheme s);
/// Parses one name; throws InputError naming `field` and listing the schemes.
Scheme parse_scheme(std::string_view text, std::string_view field = "--scheme");
/// Every scheme implemented, in report order.
std::vector<Scheme> all_schemes();

/// Where t = 0 is for a scheme's results: "switchover", "realignment" or "test_end".
std::string_view clock_of(Scheme s);

}  // namespace insmc
