#pragma once
/// One entry per reader for the libFuzzer targets (tests/fuzz/fuzz_<name>.cpp)
/// and for the corpus test that replays every kept input in the normal build
/// (tests/fuzz/corpus_test.cpp). An entry returns whether the input was
/// accepted or refused with an InputError (both normal outcomes); anything
/// else escapes: another exception, an abort, a sanitizer report. Where a
/// reader has a writer, an accepted input is also written and read back,
/// and a difference aborts.
#include <string_view>

namespace insmc::fuzz {

enum class Outcome { kAccepted, kRefused };

/// parse_record_text; an accepted file must survive write_record_file and
/// read back equal.
Outcome records(std::string_view data);
/// parse_imu_csv; the first byte chooses units, rate or time column, and
/// column names.
Outcome imu(std::string_view data);
/// check's bounds file (montecarlo/study/check/bounds_file.h).
Outcome bounds(std::string_view data);
/// The --config INI reader (montecarlo/study/run/config_file.h) and its keys'
/// checks (apps/config_options.h) with options of every kind the
/// subcommands use; then stored and notified as parse_args does.
Outcome config(std::string_view data);
/// decode_checkpoint; with the first byte odd, the rest is a body after the
/// magic line to which a valid checksum is appended (so the fuzzer reaches
/// the fields behind the checksum).
Outcome checkpoint(std::string_view data);
/// parse_quantity; the first byte chooses the dimension (or parse_rate_hz).
Outcome quantity(std::string_view data);
/// run.json's settings.arguments (montecarlo/study/run/run_file.h), as `run --from`
/// reads them: each element through the check of files of options
/// (apps/option_sources.h) with the study's options, then stored.
Outcome run_json(std::string_view data);
/// The option parser: lines of the input as the arguments of `insmc run`
/// (no --config, which would read a file), parsed, checked and turned into
/// the study with every sweep point, as run does before any work.
Outcome options(std::string_view data);

/// `insmc import-imu`, whole, on a still recording of a length, rate and
/// clock the input chooses, with its durations, interval, latitude and
/// modes; the first bytes are the choices, the rest the sensors' noise.
/// Bounded so that an input costs milliseconds (at most ~2e5 samples and
/// 2e5 output rows; larger work is the CLI tests' and the budgets'). A
/// record file written must be read back.
Outcome import_imu(std::string_view data);
/// `insmc simulate`, whole, with the runs (1 or 2), system, scheme, layout,
/// durations, filter interval, step, latitude and effects the input
/// chooses; bounded to ~2e4 rows and integration steps per run. A record
/// file written must be read back.
Outcome simulate(std::string_view data);

struct Target {
  std::string_view name;  ///< tests/fuzz/corpus/<name>, regressions/<name>, fuzz_<name>
  Outcome (*run)(std::string_view);
};
inline constexpr Target kTargets[] = {{"records", records}, {"imu", imu},               {"bounds", bounds},
                                      {"config", config},   {"checkpoint", checkpoint}, {"quantity", quantity},
                                      {"run_json", run_json}, {"options", options},
                                      {"import_imu", import_imu}, {"simulate", simulate}};

}  // namespace insmc::fuzz
