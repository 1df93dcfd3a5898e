#pragma once
/// Where an option may come from. The command line may give any option. A
/// file that carries options gives only what defines the study: a --config
/// INI file also how the results are shown (--format, --units, --quiet,
/// --full, --threads); a run.json (`run --from`) or a checkpoint (`run
/// --resume`), which insmc writes, not even that. No file may act (--help,
/// --from, --resume, --replay, another --config) or name a path insmc writes
/// (--out, --checkpoint): a downloaded run.json must never write where the
/// user did not ask (docs/robustness.md).
#include <boost/program_options/errors.hpp>
#include <string>
#include <string_view>
#include <vector>

namespace insmc::app {

enum class OptionSource {
  kCommandLine,
  kConfigFile,  ///< --config INI
  kRunFile,     ///< run.json's settings.arguments, a checkpoint's arguments
};

/// Why option `name` (long name, no dashes) may not come from `source`, as
/// the end of a one-line message; empty when it may.
std::string refused_from(std::string_view name, OptionSource source);

/// The options a run file never holds: they act, write or only show.
const std::vector<std::string>& not_in_run_files();

/// The one-line message of Boost's parse error `e`. Boost fills its
/// message by replacing %name% placeholders (%option%, %value%,
/// %original_token%, ...) with the tokens until none is left, so a token
/// holding one (`--x%value%`) made what() loop for ever; such an error is
/// told by the option's name alone.
std::string parse_error_message(const boost::program_options::error& e);

}  // namespace insmc::app
