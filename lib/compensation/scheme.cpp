#include "lib/compensation/scheme.h"

#include <string>

#include "lib/common/input_error.h"

namespace insmc {

std::string_view to_string(Scheme s) {
  switch (s) {
    case Scheme::kNone: return "none";
  }
  return "?";
}

std::vector<Scheme> all_schemes() { return {Scheme::kNone}; }

Scheme parse_scheme(std::string_view text, std::string_view field) {
  std::string names;
  for (Scheme s : all_schemes()) {
    if (to_string(s) == text) return s;
    names += (names.empty() ? "" : ", ") + std::string(to_string(s));
  }
  throw InputError(std::string(field), std::string(text), "must be one of: " + names);
}

std::string_view clock_of(Scheme s) {
  switch (s) {
    case Scheme::kNone: return "switchover";
  }
  return "?";
}

}  // namespace insmc
