#pragma once
/// Where an option may come from. The command line may give any option. A
/// file that carries options gives only what defines the study: a --config
/// INI file also how the results are shown (--format, --units, --quiet,
/// --full, --threads); a run.json (`run --from`) or a checkpoint (`run
/// --resume`), which insmc writes, not even that. No file may act (--help,
/// --from, --resume, --replay, another --config) or name a path insmc writes
/// (--out, --checkpoint): a downloaded run.json must never write where the
/// user did not ask (docs/robustness.md). A file gives values of options by
/// name and is never parsed as a command line: every file of options goes
/// through one check (FileOptions), so a `--` separator or a word after it
/// cannot smuggle an option past it. Here too the options a file keeps
/// (explicit_arguments) and the options typed (given_options); the files
/// themselves are read by montecarlo/study/run/config_file.h,
/// montecarlo/study/run/run_file.h and montecarlo/study/run/checkpoint.h.
#include <boost/program_options.hpp>
#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "apps/subcommands.h"

namespace insmc::app {

namespace po = boost::program_options;

enum class OptionSource {
  kCommandLine,
  kConfigFile,  ///< --config INI
  kRunFile,     ///< run.json's settings.arguments, a checkpoint's arguments
};

/// The options a run file never holds: they act, write or only show.
const std::vector<std::string>& not_in_run_files();

/// One option a file of options gives, by name: a `key = value` line of a
/// --config INI file, or an element of a run file's arguments (`--name=value`,
/// `--name` for a switch).
struct FileOption {
  std::string name;
  std::optional<std::string> value;  ///< none: a switch given bare (run files only)
};

/// The one check every file of options passes, option by option: a file
/// gives values of the subcommand's options by their exact long names; it is
/// never parsed as a command line (no `--`, no positional word, no short or
/// abbreviated option, no option given twice unless it may repeat), and an
/// option refused_from() its source is refused. What passes is kept as
/// Boost's parsed options, stored under the command line's (apps/cli_common.h).
class FileOptions {
 public:
  FileOptions(const po::options_description& options, OptionSource source);
  /// Takes `option`, or returns why it is refused (the end of a one-line
  /// message naming the option; the caller names the file and the place).
  std::string take(const FileOption& option, std::size_t place);
  const po::parsed_options& parsed() const { return parsed_; }

 private:
  const po::options_description& options_;
  OptionSource source_;
  po::parsed_options parsed_;
  std::map<std::string, std::size_t> first_place_;  ///< of each option that may be given once
};

/// The arguments a run file kept (run.json's settings.arguments, a
/// checkpoint's arguments) as options of `options`, each through
/// FileOptions; `field` and `file` name the file (--from DIR/run.json,
/// --resume FILE) and `list` its list ("settings.arguments") in the
/// InputError thrown at the first element refused.
po::parsed_options run_file_options(const std::vector<std::string>& elements, const po::options_description& options,
                                    const std::string& field, const std::string& file, std::string_view list);

/// The one-line message of Boost's parse error `e`. Boost fills its
/// message by replacing %name% placeholders (%option%, %value%,
/// %original_token%, ...) with the tokens until none is left, so a token
/// holding one (`--x%value%`) made what() loop for ever; such an error is
/// told by the option's name alone.
std::string parse_error_message(const boost::program_options::error& e);

/// The options of `options` that `vm` holds other than by default, each as
/// `--name=value` (one per value of a repeatable option; a switch as
/// `--name`), in the order of `options`, leaving out those named in `drop`.
Args explicit_arguments(const po::variables_map& vm, const po::options_description& options,
                        const std::vector<std::string>& drop);

/// The options of a command line as (name, tokens) pairs: `options` plus the
/// --help and --config that parse_args adds. Names are canonical (an
/// abbreviation like --samp is reported as "samples").
struct GivenOption {
  std::string name;
  Args tokens;  ///< as typed: {"--out", "DIR"} or {"--out=DIR"}
};
std::vector<GivenOption> given_options(const Args& args, const po::options_description& options);

}  // namespace insmc::app
