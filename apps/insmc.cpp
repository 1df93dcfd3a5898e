// insmc: dispatches `insmc <subcommand> [options]` to apps/cmd_<subcommand>.cpp
// and turns bad input into one line on stderr and exit code 2.
#include <boost/program_options/errors.hpp>
#include <cstdio>
#include <exception>
#include <fmt/core.h>
#include <malloc.h>
#include <new>
#include <string_view>

#include "apps/option_sources.h"
#include "apps/subcommands.h"
#include "lib/common/input_error.h"
#include "lib/common/version.h"

namespace {

struct Subcommand {
  std::string_view name;
  int (*run)(const insmc::app::Args&);
  std::string_view summary;
};

constexpr Subcommand kSubcommands[] = {
    {"run", insmc::app::run_run, "Monte Carlo study: RMS position-error envelopes with confidence intervals"},
    {"covariance", insmc::app::run_covariance, "exact linear-covariance envelopes and the error budget"},
    {"rank", insmc::app::run_rank, "the schemes in order with its significance, and the break-even assumptions"},
    {"check", insmc::app::run_check, "statistical bounds for CI: exit 1 when a bound is violated"},
    {"tables", insmc::app::run_tables, "the report's tables beside the values insmc computes"},
    {"simulate", insmc::app::run_simulate, "truth-level records (format v1) with chosen named effects"},
    {"import-imu", insmc::app::run_import_imu, "records (format v1) from raw IMU samples: strapdown, stationary base"},
    {"noise", insmc::app::run_noise, "raw-sensor noise: Allan deviation, fitted noise terms, warm-up, disturbances"},
    {"gap", insmc::app::run_gap, "sim-to-real gap diagnosis of record files: where, which effect, how far it shrinks"},
    {"gap-validate", insmc::app::run_gap_validate, "the gap diagnosis scored blind on records with withheld effects"},
    {"compensate", insmc::app::run_compensate, "one unit from its test run: estimates, each scheme's envelope, go / no-go"},
    {"effects", insmc::app::run_effects, "the truth simulator's named effects, parameters and defaults"},
    {"params", insmc::app::run_params, "the uncertainty catalogue: names, symbols, units, bounds"},
    {"bench", insmc::app::run_bench, "throughput of the Monte Carlo paths against the machine's floor"},
};

void print_usage(std::FILE* out) {
  fmt::print(out,
             "insmc {}: Monte Carlo covariance analysis of preflight test procedures for a\n"
             "space-stabilized inertial navigation system (Johansen, MIT RE-59, 1969).\n\n"
             "usage: insmc <subcommand> [options]     insmc <subcommand> --help\n"
             "       insmc --version\n\nsubcommands:\n",
             insmc::kVersion);
  for (const auto& s : kSubcommands) fmt::print(out, "  {:<12} {}\n", s.name, s.summary);
}

}  // namespace

int main(int argc, char** argv) {
  // The gap diagnosis allocates and frees matrices of a few MB per grid
  // point on every thread; by default glibc hands such blocks back to the
  // kernel and faults them in again (measured: a third of gap-validate's
  // wall time in page faults). Keep them in the heap instead.
  mallopt(M_MMAP_THRESHOLD, 256 << 20);
  mallopt(M_TRIM_THRESHOLD, 512 << 20);
  if (argc < 2) {
    print_usage(stderr);
    return 2;
  }
  const std::string_view first = argv[1];
  if (first == "--help" || first == "-h" || first == "help") {
    print_usage(stdout);
    return 0;
  }
  if (first == "--version") {
    fmt::print("insmc {}\n", insmc::kVersion);
    return 0;
  }
  for (const auto& sub : kSubcommands) {
    if (sub.name != first) continue;
    const insmc::app::Args args(argv + 2, argv + argc);
    try {
      return sub.run(args);
    } catch (const insmc::InputError& e) {
      fmt::print(stderr, "insmc {}: {}\n", sub.name, e.what());
      return 2;
    } catch (const boost::program_options::error& e) {
      fmt::print(stderr, "insmc {}: {} (see insmc {} --help)\n", sub.name, insmc::app::parse_error_message(e),
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
