#pragma once
/// The options of a `--config FILE`: each key of the INI file (read by
/// montecarlo/study/run/config_file.h) names an option of the subcommand, by its
/// long name. Every mistake is an InputError whose one-line message starts
/// `FILE:LINE: ` and names the key.
#include <boost/program_options.hpp>
#include <cstddef>
#include <string>
#include <string_view>

namespace insmc::app {

/// Cap: a study file holds tens of options; key = value lines: 10,000.
inline constexpr std::size_t kMaxConfigEntries = 10'000;

/// Parses INI text into options of `options`, each value checked by its
/// option's type. Refuses, besides what the INI reader refuses, an unknown
/// key, an option a file may not give (apps/option_sources.h), a key given
/// twice (unless the option may repeat, like --bound), a value the option
/// cannot take; `source` names the file in messages.
boost::program_options::parsed_options parse_config_text(std::string_view text, std::string_view source,
                                                         const boost::program_options::options_description& options);

/// Reads `path` (mc::read_config_file) and stores its options into `vm`
/// under those already there (the command line wins).
void store_config_file(const std::string& path, const boost::program_options::options_description& options,
                       boost::program_options::variables_map& vm);

}  // namespace insmc::app
