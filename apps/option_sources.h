#pragma once
/// Where an option may come from. The command line may give any option. A
/// file that carries options gives only what defines the study: a --config
/// INI file also how the results are shown (--format, --units, --quiet,
/// --full, --threads); a run.json (`run --from`) or a checkpoint (`run
/// --resume`), which insmc writes, not even that. No file may act (--help,
/// --from, --resume, --replay, another --config) or name a path insmc writes
/// (--out, --checkpoint): a downloaded run.json must never write where the
/// user did not ask (docs/robustness.md). Here too the options a file keeps
/// (explicit_arguments) and how a file's options meet those typed beside
/// them (given_options, without_options); the files themselves are read by
/// montecarlo/study/run_file.h and montecarlo/study/checkpoint.h.
#include <boost/program_options.hpp>
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

/// The tokens of `given` without the options named in `drop`.
Args without_options(const std::vector<GivenOption>& given, const std::vector<std::string>& drop);

}  // namespace insmc::app
