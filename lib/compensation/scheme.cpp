#include "lib/compensation/scheme.h"

#include <string>

#include "lib/common/input_error.h"

namespace insmc {

std::string_view to_string(Scheme s) {
  switch (s) {
    case Scheme::kNone: return "none";
    case Scheme::k5_1_1: return "5.1.1";
    case Scheme::k5_1_2: return "5.1.2";
    case Scheme::kCombined: return "combined";
    case Scheme::k5_2: return "5.2";
    case Scheme::k5_3: return "5.3";
    case Scheme::k5_4: return "5.4";
  }
  return "?";
}

std::vector<Scheme> all_schemes() {
  return {Scheme::kNone, Scheme::k5_1_1, Scheme::k5_1_2, Scheme::kCombined,
          Scheme::k5_2,  Scheme::k5_3,   Scheme::k5_4};
}

Scheme parse_scheme(std::string_view text, std::string_view field) {
  std::string names;
  for (Scheme s : all_schemes()) {
    if (to_string(s) == text) return s;
    names += (names.empty() ? "" : ", ") + std::string(to_string(s));
  }
  throw InputError(std::string(field), std::string(text), "must be one of: " + names + " (or all)");
}

std::string_view clock_of(Scheme s) {
  if (realigns(s)) return "realignment";
  if (resets_at_test_end(s)) return "test_end";
  return "switchover";
}

bool realigns(Scheme s) { return s == Scheme::k5_1_1 || s == Scheme::k5_1_2 || s == Scheme::kCombined; }
bool resets_at_test_end(Scheme s) { return s == Scheme::k5_2 || s == Scheme::k5_3; }
bool uses_test_run(Scheme s) { return s != Scheme::kNone && s != Scheme::k5_4; }
bool uses_alignment_data(Scheme s) { return s == Scheme::k5_4; }

double clock_start_s(Scheme s, double T, double nav_start_s) {
  return realigns(s) ? nav_start_s : resets_at_test_end(s) ? T : 0.0;
}

double ready_time_s(Scheme s, double T, double realignment_duration_s) {
  return realigns(s) ? T + realignment_duration_s : resets_at_test_end(s) ? T : 0.0;
}

double frame_time_offset_s(Scheme s, double T) { return resets_at_test_end(s) ? T : 0.0; }

}  // namespace insmc
