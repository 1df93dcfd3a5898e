#include "apps/dispatch.h"

#include <boost/program_options/errors.hpp>
#include <exception>
#include <fmt/core.h>
#include <new>

#include "apps/option_sources.h"
#include "lib/common/input_error.h"
#include "lib/common/version.h"

namespace insmc::app {

namespace {

/// The usage text with `subcommands`' names and summaries.
void print_usage(std::FILE* out, std::span<const Subcommand> subcommands) {
  fmt::print(out,
             "insmc {}: Monte Carlo covariance analysis of preflight test procedures for a\n"
             "space-stabilized inertial navigation system (Johansen, MIT RE-59, 1969).\n\n"
             "usage: insmc <subcommand> [options]     insmc <subcommand> --help\n"
             "       insmc --version\n\nsubcommands:\n",
             insmc::kVersion);
  for (const auto& s : subcommands) fmt::print(out, "  {:<12} {}\n", s.name, s.summary);
}

}  // namespace

int dispatch(std::span<const Subcommand> subcommands, int argc, const char* const* argv) {
  if (argc < 2) {
    print_usage(stderr, subcommands);
    return 2;
  }
  const std::string_view first = argv[1];
  if (first == "--help" || first == "-h" || first == "help") {
    print_usage(stdout, subcommands);
    return 0;
  }
  if (first == "--version") {
    fmt::print("insmc {}\n", kVersion);
    return 0;
  }
  for (const auto& sub : subcommands) {
    if (sub.name != first) continue;
    const Args args(argv + 2, argv + argc);
    try {
      return sub.run(args);
    } catch (const InputError& e) {
      fmt::print(stderr, "insmc {}: {}\n", sub.name, e.what());
      return 2;
    } catch (const boost::program_options::error& e) {
      fmt::print(stderr, "insmc {}: {} (see insmc {} --help)\n", sub.name, parse_error_message(e),
                 sub.name);
      return 2;
    } catch (const std::bad_alloc&) {
      // Every input is capped (docs/robustness.md), but the caps allow more
      // than a small machine holds: the user can fix this one.
      fmt::print(stderr, "insmc {}: not enough memory for this input (fewer samples, threads, runs or rows)\n",
                 sub.name);
      return 2;
    } catch (const std::exception& e) {
      fmt::print(stderr, "insmc {}: error: {}\n", sub.name, e.what());
      return 3;
    }
  }
  fmt::print(stderr, "insmc: unknown subcommand '{}'; run insmc --help for the list\n", first);
  return 2;
}

}  // namespace insmc::app
