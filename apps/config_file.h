#pragma once
/// The INI file of `--config FILE`: `key = value` lines naming any option of
/// the subcommand (`[section]` lines prefix the keys with `section.`, as
/// Boost's config-file parser does), `#` comments, blank lines, an optional
/// UTF-8 byte-order mark. Every mistake is an InputError whose one-line
/// message starts `FILE:LINE: ` and names the key.
#include <boost/program_options.hpp>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace insmc::app {

/// Caps: a study file holds tens of options; sweeps make a value long.
/// The file: 1 MiB; a line: 16 KiB; key = value lines: 10,000.
inline constexpr std::uint64_t kMaxConfigFileBytes = std::uint64_t{1} << 20;
inline constexpr std::size_t kMaxConfigLineBytes = 16 * 1024;
inline constexpr std::size_t kMaxConfigEntries = 10'000;

/// Parses INI text into options of `options`, each value checked by its
/// option's type. Refuses a line that is not `key = value`, an unknown key,
/// a key given twice (unless the option may repeat, like --bound), a value
/// the option cannot take; `source` names the file in messages.
boost::program_options::parsed_options parse_config_text(std::string_view text, std::string_view source,
                                                         const boost::program_options::options_description& options);

/// Reads `path` (at most kMaxConfigFileBytes; a directory, an unreadable
/// file or a read error is an InputError, never an empty config) and stores
/// its options into `vm` under those already there (the command line wins).
void store_config_file(const std::string& path, const boost::program_options::options_description& options,
                       boost::program_options::variables_map& vm);

}  // namespace insmc::app
