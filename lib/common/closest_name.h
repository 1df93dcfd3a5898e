#pragma once
/// "Did you mean": the known name closest to a misspelled one, by edit
/// distance, for the one-line errors of options and effect names.
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace insmc {

/// The name of `known` nearest to `typed` (Levenshtein distance, ties to the
/// first), when it is near enough to be a slip: at most max(2, |typed|/3)
/// edits, or one name beginning the other (at least 4 characters). Names
/// equal to `typed` are not suggested.
std::optional<std::string> closest_name(std::string_view typed, std::span<const std::string> known);

/// " (did you mean X?)" for closest_name's answer, else "".
std::string did_you_mean(std::string_view typed, std::span<const std::string> known);

}  // namespace insmc
