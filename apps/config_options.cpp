#include "apps/config_options.h"

#include <fmt/format.h>

#include "apps/option_sources.h"
#include "montecarlo/study/run/config_file.h"

namespace insmc::app {

po::parsed_options parse_config_text(std::string_view text, std::string_view source,
                                     const po::options_description& options) {
  FileOptions check(options, OptionSource::kConfigFile);  // the check of every file of options
  std::size_t entries = 0;
  mc::read_config_text(text, source, [&](const mc::ConfigEntry& entry) -> std::string {
    if (++entries > kMaxConfigEntries)
      return fmt::format("more than {} options: a --config file may hold at most {}", kMaxConfigEntries,
                         kMaxConfigEntries);
    return check.take({entry.key, entry.value}, entry.line);
  });
  return check.parsed();
}

void store_config_file(const std::string& path, const po::options_description& options, po::variables_map& vm) {
  po::store(parse_config_text(mc::read_config_file(path), path, options), vm);
}

}  // namespace insmc::app
