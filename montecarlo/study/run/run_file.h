#pragma once
/// run.json as the run (docs/outputs.md): `insmc run` keeps the options that
/// made its numbers in `settings.arguments` (every option given on the
/// command line or in a --config file, in canonical `--name=value` form,
/// without the ones that choose where and how the results are shown), and
/// `insmc run --from DIR/run.json` runs them again.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace insmc::mc {

/// Caps of the reader: run.json is the envelope and the settings, some
/// hundred kilobytes; the arguments are a few dozen.
inline constexpr std::uint64_t kMaxRunJsonBytes = std::uint64_t{64} << 20;
inline constexpr std::size_t kMaxRunArguments = 10'000;
inline constexpr std::size_t kMaxRunArgumentBytes = 64 * 1024;

/// settings.arguments of a run.json text; throws InputError naming `source`
/// when the text is not JSON, lacks the array, or an element is not a
/// string starting with "--" (or breaks a cap).
std::vector<std::string> run_arguments_from_json(std::string_view text, std::string_view source);

/// The same from a file, parsed as it is read (never held whole), with the
/// size cap.
std::vector<std::string> read_run_arguments(const std::string& path);

}  // namespace insmc::mc
