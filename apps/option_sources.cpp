#include "apps/option_sources.h"

#include <algorithm>
#include <array>
#include <fmt/format.h>
#include <stdexcept>

#include "lib/common/input_error.h"
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

/// Why option `name` (long name, no dashes) may not come from `source`, as
/// the end of a one-line message; empty when it may.
std::string refused_from(std::string_view name, OptionSource source) {
  if (source == OptionSource::kCommandLine) return {};
  if (among(kActs, name)) return "acts rather than defines the study: give it on the command line";
  if (among(kWrites, name)) return "names where insmc writes: a file of options may not; give it on the command line";
  if (source == OptionSource::kRunFile && among(kShows, name))
    return "only chooses how results are shown, which insmc never keeps in a run file";
  return {};
}

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
      return key == "value" ? echo_input(named->get_option_name()) + " = " + echo_input(value) + ": no '%' in a value (95% is 0.95)"
                            : "the option " + echo_input(named->get_option_name()) + " is not understood (it holds a '%')";
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

FileOptions::FileOptions(const po::options_description& options, OptionSource source)
    : options_(options), source_(source), parsed_(&options) {}

std::string FileOptions::take(const FileOption& option, std::size_t place) {
  const bool ini = source_ == OptionSource::kConfigFile;
  const std::string& name = option.name;
  // Refused by name first, whether or not the subcommand has the option.
  if (const std::string why = refused_from(name, source_); !why.empty())
    return ini ? fmt::format("{}: {}", name, why) : fmt::format("holds --{}, which {}", name, why);
  // Exact long names only: Boost would also match a short name ("-h") or,
  // on a command line, an abbreviation.
  const po::option_description* d = options_.find_nothrow(name, /*approx=*/false);
  if (d == nullptr || d->long_name() != name)
    return ini ? fmt::format("unknown option '{}' (the keys are the long option names, without --)", echo_input(name))
               : fmt::format("names an unknown option '{}' (the long option names of insmc run)", echo_input(name));
  const po::value_semantic& semantic = *d->semantic();
  std::vector<std::string> tokens;
  if (option.value) {
    if (!ini && semantic.max_tokens() == 0) return fmt::format("gives --{} a value; it is a switch, kept bare", name);
    tokens.push_back(*option.value);
  } else if (semantic.min_tokens() > 0) {
    return fmt::format("gives --{} no value (--{}=VALUE)", name, name);
  }
  if (!semantic.is_composing()) {
    const auto [it, inserted] = first_place_.emplace(name, place);
    if (!inserted)
      return ini ? fmt::format("{} given twice (first on line {})", name, it->second)
                 : fmt::format("gives --{} twice (first in [{}])", name, it->second);
  }
  // Each value on its own first, so that a bad one is named where it is.
  po::parsed_options one(&options_);
  one.options.emplace_back(name, tokens);
  try {
    po::variables_map scratch;
    po::store(one, scratch);
  } catch (const po::error&) {
    const std::string value = echo_input(option.value.value_or(""));
    return ini ? fmt::format("{} = '{}': not a value this option takes (see --help)", name, value)
               : fmt::format("gives --{} the value '{}', which it does not take (see --help)", name, value);
  }
  parsed_.options.emplace_back(name, std::move(tokens));
  return {};
}

namespace {

/// An element of a run file's arguments as the option it names:
/// `--name=value`, or `--name` (a switch); none when it is anything else (a
/// `--` separator, a bare word, a short option, an empty name).
std::optional<FileOption> option_of_element(std::string_view element) {
  if (!element.starts_with("--")) return std::nullopt;
  element.remove_prefix(2);
  const std::size_t eq = element.find('=');
  const std::string_view name = element.substr(0, eq);
  if (name.empty() || name.front() == '-') return std::nullopt;
  FileOption option{std::string(name), std::nullopt};
  if (eq != std::string_view::npos) option.value = std::string(element.substr(eq + 1));
  return option;
}

}  // namespace

po::parsed_options run_file_options(const std::vector<std::string>& elements, const po::options_description& options,
                                    const std::string& field, const std::string& file, std::string_view list) {
  FileOptions check(options, OptionSource::kRunFile);
  for (std::size_t i = 0; i < elements.size(); ++i) {
    const std::optional<FileOption> option = option_of_element(elements[i]);
    const std::string why =
        option ? check.take(*option, i)
               : fmt::format("= '{}' is not an option by name (each element is --NAME=VALUE, or --NAME for a "
                             "switch, never a command line)",
                             echo_input(elements[i], 60));
    if (!why.empty()) throw InputError(field, echo_input(file, 256), fmt::format("{}[{}] {}", list, i, why));
  }
  return check.parsed();
}

Args explicit_arguments(const po::variables_map& vm, const po::options_description& options,
                        const std::vector<std::string>& drop) {
  Args out;
  for (const auto& option : options.options()) {
    const std::string& name = option->long_name();
    if (!vm.count(name) || vm[name].defaulted() || std::find(drop.begin(), drop.end(), name) != drop.end()) continue;
    const boost::any& v = vm[name].value();
    if (const auto* s = boost::any_cast<std::string>(&v)) {
      out.push_back(fmt::format("--{}={}", name, *s));
    } else if (const auto* list = boost::any_cast<std::vector<std::string>>(&v)) {
      for (const std::string& e : *list) out.push_back(fmt::format("--{}={}", name, e));
    } else if (const auto* d = boost::any_cast<double>(&v)) {
      out.push_back(fmt::format("--{}={}", name, *d));  // shortest exact round trip
    } else if (const auto* i = boost::any_cast<int>(&v)) {
      out.push_back(fmt::format("--{}={}", name, *i));
    } else if (const auto* b = boost::any_cast<bool>(&v)) {
      if (*b) out.push_back("--" + name);
    } else {
      throw std::logic_error("option --" + name + " has a type run.json cannot keep");
    }
  }
  return out;
}

std::vector<GivenOption> given_options(const Args& args, const po::options_description& options) {
  po::options_description all;
  all.add(options);
  all.add_options()("help,h", "")("config", po::value<std::string>(), "");  // as parse_args adds them
  const po::parsed_options parsed = po::command_line_parser(args).options(all).run();
  std::vector<GivenOption> out;
  for (const po::option& o : parsed.options) out.push_back({o.string_key, o.original_tokens});
  return out;
}

}  // namespace insmc::app
