#include "apps/option_sources.h"

#include <algorithm>
#include <array>

#include "lib/common/input_text.h"

namespace insmc::app {
namespace {

/// Options that do something besides defining the study.
constexpr std::array<std::string_view, 5> kActs = {"help", "config", "from", "resume", "replay"};
/// Options that name a path insmc writes.
constexpr std::array<std::string_view, 3> kWrites = {"out", "checkpoint", "checkpoint-every"};
/// Options that choose how results are shown, not what they are.
constexpr std::array<std::string_view, 5> kShows = {"format", "quiet", "full", "threads", "json"};

template <std::size_t N>
bool among(const std::array<std::string_view, N>& names, std::string_view name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

}  // namespace

std::string refused_from(std::string_view name, OptionSource source) {
  if (source == OptionSource::kCommandLine) return {};
  if (among(kActs, name)) return "acts rather than defines the study: give it on the command line";
  if (among(kWrites, name)) return "names where insmc writes: a file of options may not; give it on the command line";
  if (source == OptionSource::kRunFile && among(kShows, name))
    return "only chooses how results are shown, which insmc never keeps in a run file";
  return {};
}

namespace {
/// Boost keeps the substitutions protected; a pointer to the member, taken
/// through a derived class, reads them from any error (a legal access).
struct SubstitutionsOf : boost::program_options::error_with_option_name {
  static constexpr auto kMember = &SubstitutionsOf::m_substitutions;
};
}  // namespace

std::string parse_error_message(const boost::program_options::error& e) {
  const auto* named = dynamic_cast<const boost::program_options::error_with_option_name*>(&e);
  if (named == nullptr) return e.what();
  for (const auto& [key, value] : named->*SubstitutionsOf::kMember)
    if (value.find('%') != std::string::npos)
      return "the option " + echo_input(named->get_option_name()) + " is not understood (it holds a '%')";
  return e.what();
}

const std::vector<std::string>& not_in_run_files() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> out;
    for (std::string_view n : kActs) out.emplace_back(n);
    for (std::string_view n : kWrites) out.emplace_back(n);
    for (std::string_view n : kShows) out.emplace_back(n);
    return out;
  }();
  return names;
}

}  // namespace insmc::app
