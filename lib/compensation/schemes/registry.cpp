// The scheme registry: the report's schemes in report order (their index
// is Scheme::k...), then any registered later. A new scheme is one file in
// this folder and one line here.
#include <stdexcept>
#include <string>

#include "lib/common/input_error.h"
#include "lib/compensation/scheme.h"
#include "lib/compensation/schemes/schemes.h"

namespace insmc {
namespace {

std::vector<const SchemeDefinition*>& registry() {
  static std::vector<const SchemeDefinition*> r = {
      &schemes::none(),       &schemes::scheme_5_1_1(), &schemes::scheme_5_1_2(), &schemes::combined(),
      &schemes::scheme_5_2(), &schemes::scheme_5_3(),   &schemes::scheme_5_4(),
  };
  return r;
}

}  // namespace

const SchemeDefinition& Scheme::definition() const {
  const auto& r = registry();
  if (index_ < 0 || static_cast<std::size_t>(index_) >= r.size())
    throw std::logic_error("scheme index " + std::to_string(index_) + " is not in the registry");
  return *r[static_cast<std::size_t>(index_)];
}

Scheme register_scheme(const SchemeDefinition& definition) {
  auto& r = registry();
  for (const SchemeDefinition* d : r)
    if (d->name == definition.name) throw std::logic_error("scheme " + std::string(definition.name) + " is registered already");
  r.push_back(&definition);
  return Scheme(static_cast<int>(r.size() - 1));
}

std::string_view to_string(Scheme s) { return s.definition().name; }

std::vector<Scheme> all_schemes() {
  std::vector<Scheme> out;
  for (std::size_t i = 0; i < registry().size(); ++i) out.emplace_back(static_cast<int>(i));
  return out;
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

bool realigns(Scheme s) { return s.definition().realigns; }
bool resets_at_test_end(Scheme s) { return s.definition().resets_at_test_end; }
bool uses_test_run(Scheme s) { return s.definition().uses_test_run; }
bool uses_alignment_data(Scheme s) { return s.definition().uses_alignment_data; }

double clock_start_s(Scheme s, double T, double nav_start_s) {
  return realigns(s) ? nav_start_s : resets_at_test_end(s) ? T : 0.0;
}

double ready_time_s(Scheme s, double T, double realignment_duration_s) {
  return realigns(s) ? T + realignment_duration_s : resets_at_test_end(s) ? T : 0.0;
}

double frame_time_offset_s(Scheme s, double T) { return resets_at_test_end(s) ? T : 0.0; }

}  // namespace insmc
