#include "apps/config_options.h"

#include <fmt/format.h>

#include <map>
#include <vector>

#include "apps/option_sources.h"
#include "lib/common/input_text.h"
#include "montecarlo/study/config_file.h"

namespace insmc::app {

po::parsed_options parse_config_text(std::string_view text, std::string_view source,
                                     const po::options_description& options) {
  po::parsed_options parsed(&options);
  std::map<std::string, std::size_t> first_line;  // of each option that may be given once
  mc::read_config_text(text, source, [&](const mc::ConfigEntry& entry) -> std::string {
    const std::string& key = entry.key;
    const po::option_description* d = options.find_nothrow(key, /*approx=*/false);
    if (d == nullptr)
      return fmt::format("unknown option '{}' (the keys are the long option names, without --)", echo_input(key));
    if (const std::string why = refused_from(d->long_name(), OptionSource::kConfigFile); !why.empty())
      return fmt::format("{}: {}", key, why);
    if (parsed.options.size() >= kMaxConfigEntries)
      return fmt::format("more than {} options: a --config file may hold at most {}", kMaxConfigEntries,
                         kMaxConfigEntries);
    if (!d->semantic()->is_composing()) {
      const auto [it, inserted] = first_line.emplace(key, entry.line);
      if (!inserted) return fmt::format("{} given twice (first on line {})", key, it->second);
    }
    // Each value on its own first, so that a bad one is named with its line.
    po::parsed_options one(&options);
    one.options.emplace_back(key, std::vector<std::string>{entry.value});
    try {
      po::variables_map scratch;
      po::store(one, scratch);
    } catch (const po::error&) {
      return fmt::format("{} = '{}': not a value this option takes (see --help)", key, echo_input(entry.value));
    }
    parsed.options.emplace_back(key, std::vector<std::string>{entry.value});
    return {};
  });
  return parsed;
}

void store_config_file(const std::string& path, const po::options_description& options, po::variables_map& vm) {
  po::store(parse_config_text(mc::read_config_file(path), path, options), vm);
}

}  // namespace insmc::app
