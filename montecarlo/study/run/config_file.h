#pragma once
/// The INI file of `--config FILE`: `key = value` lines (`[section]` lines
/// prefix the keys with `section.`, as Boost's config-file parser does),
/// `#` comments, blank lines, an optional UTF-8 byte-order mark. Every
/// mistake is an InputError whose one-line message starts `FILE:LINE: `.
/// What the keys mean (the options of a subcommand) is the command line's
/// business: apps/config_options.h checks each entry as it is read.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>

namespace insmc::mc {

/// Caps: a study file holds tens of options; sweeps make a value long.
/// The file: 1 MiB; a line: 16 KiB.
inline constexpr std::uint64_t kMaxConfigFileBytes = std::uint64_t{1} << 20;
inline constexpr std::size_t kMaxConfigLineBytes = 16 * 1024;

/// One `key = value` line, both trimmed.
struct ConfigEntry {
  std::string key;        ///< with the prefix of the [section] above it
  std::string value;
  std::size_t line = 0;   ///< 1-based
};

/// Reads INI text line by line and hands every entry to `take` in file
/// order. `take` returns an empty string to accept the entry, or why it
/// refuses it, which is thrown like a mistake of the text itself
/// (`SOURCE:LINE: why`), so the first mistake of the file is the one told.
/// Refuses a line that is not `key = value` or `[section]`, an empty key and
/// a line longer than kMaxConfigLineBytes; `source` names the file.
void read_config_text(std::string_view text, std::string_view source,
                      const std::function<std::string(const ConfigEntry&)>& take);

/// The text of `path`, at most kMaxConfigFileBytes; a directory, an
/// unreadable file or a read error is an InputError, never an empty config.
std::string read_config_file(const std::string& path);

}  // namespace insmc::mc
