#include "lib/common/closest_name.h"

#include <algorithm>
#include <vector>

namespace insmc {
namespace {

/// Edits (insert, delete, substitute) from a to b; stops counting at `cap`.
std::size_t edit_distance(std::string_view a, std::string_view b, std::size_t cap) {
  if (a.size() > b.size() + cap || b.size() > a.size() + cap) return cap + 1;
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = up;
    }
  }
  return row[b.size()];
}

bool begins(std::string_view whole, std::string_view part) {
  return part.size() >= 4 && whole.size() > part.size() && whole.substr(0, part.size()) == part;
}

}  // namespace

std::optional<std::string> closest_name(std::string_view typed, std::span<const std::string> known) {
  // Names are short; a typed value past this is not a slip of one.
  constexpr std::size_t kLongest = 64;
  if (typed.empty() || typed.size() > kLongest) return std::nullopt;
  const std::size_t allowed = std::max<std::size_t>(2, typed.size() / 3);
  std::optional<std::string> best;
  std::size_t best_distance = allowed + 1;
  for (const std::string& name : known) {
    if (name == typed || name.size() > kLongest) continue;
    std::size_t d = edit_distance(typed, name, allowed);
    if (d > allowed && (begins(typed, name) || begins(name, typed))) d = allowed;
    if (d < best_distance) best_distance = d, best = name;
  }
  return best;
}

std::string did_you_mean(std::string_view typed, std::span<const std::string> known) {
  const std::optional<std::string> name = closest_name(typed, known);
  return name ? " (did you mean " + *name + "?)" : "";
}

}  // namespace insmc
