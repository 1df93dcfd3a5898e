#pragma once
/// What every subcommand shares: option parsing (command line, then an INI
/// file given by --config; the command line wins), --help, the output
/// format and the files of --out DIR (checked before the work and written
/// as one set after it: apps/output_paths.h).
#include <boost/program_options.hpp>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "apps/subcommands.h"
#include "lib/common/input_text.h"
#include "lib/common/model_options.h"
#include "montecarlo/records/gap/validation/writer_conventions.h"
#include "montecarlo/report/report.h"

namespace insmc::app {

namespace po = boost::program_options;


/// Whether a comma list in a sweepable option (--latitude, --test-duration,
/// --bound NAME=..., apps/sweep.h) is a sweep (`run`) or refused: every
/// other subcommand takes one value, and never silently the first of a list.
enum class Lists { kOneValue, kSweeps };

/// Parses `args` with `options` (plus --help and --config FILE). Prints the
/// help text and returns nullopt when --help is given.
std::optional<po::variables_map> parse_args(const Args& args, const std::string& subcommand,
                                            const std::string& synopsis, const po::options_description& options,
                                            Lists lists = Lists::kOneValue);
/// The options of a run given again by a file (`run --from`, `run
/// --resume`): those of this command line but `own` (the option naming the
/// file), with `added`; then those the file kept (`kept`, each checked by
/// apps/option_sources.h, never parsed as a command line) that the command
/// line does not give; then --config's. As parse_args, but --help is an error.
po::variables_map parse_args_with_file(const Args& args, const std::string& own, const po::parsed_options& kept,
                                       const po::options_description& options,
                                       const std::vector<po::option>& added = {});

/// A count (samples, seed, runs) as an integer ("100000") or in exponent
/// form when that is a whole number ("1e5"), up to 2^53 there; a sign, a
/// fraction or anything else is an InputError naming `field`. Options that
/// take one are strings, so that "-1" never wraps to 2^64 − 1.
std::uint64_t parse_count(const std::string& text, const std::string& field);
/// The count of option `name` (its value or default).
std::uint64_t read_count(const po::variables_map& vm, const std::string& name);

/// The value of option "layout": own, foreign or fuzzed (else an InputError;
/// montecarlo/records/gap/validation/writer_conventions.h).
gap::RecordWriter read_record_writer(const po::variables_map& vm);

/// --latitude and the loop gains: the ModelOptions every model command takes.
po::options_description model_options_description();
/// Reads them; `system2_used` enables the |L0| < 90° check of (2.16).
ModelOptions read_model_options(const po::variables_map& vm, bool system2_used);

/// `read()`, the reader of input file `path` given with `option`: a file
/// that cannot be opened or read is named with its option ("--records =
/// PATH: cannot open the record file: ..."); what is wrong inside it keeps
/// its FILE:LINE:COLUMN message.
template <class Read>
auto read_input(const std::string& option, const std::string& path, Read&& read) {
  try {
    return read();
  } catch (const FileReadError& e) {
    throw InputError(option, echo_input(path, 256), e.why());
  }
}

}  // namespace insmc::app
