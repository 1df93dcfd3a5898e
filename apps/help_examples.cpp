#include "apps/help_examples.h"

#include <array>

namespace insmc::app {
namespace {

struct Examples {
  std::string_view subcommand;
  std::array<std::string_view, 2> lines;
};

// Each runs as written (tests/cli/help_examples_test.cpp runs the ones that
// need no input file of the user's).
constexpr Examples kExamples[] = {
    {"run", {"insmc run --samples 100000 --system 1 --out study", "insmc run --test-duration 5min,10min,15min,20min --out sweep"}},
    {"covariance", {"insmc covariance --system 2 --out covariance", ""}},
    {"rank", {"insmc rank --system 1 --out ranking", ""}},
    {"check", {"insmc check --bounds bounds.txt --samples 200000", ""}},
    {"tables", {"insmc tables --format csv --out tables", ""}},
    {"simulate", {"insmc simulate --runs 20 --effect thermal_transient:bias=0.2mg,drift=3meru --out runs.csv", ""}},
    {"import-imu", {"insmc import-imu --input run1.csv --input run2.csv --rate 100Hz --latitude 51deg --out records.csv", ""}},
    {"noise", {"insmc noise --input run1.csv --rate 100Hz --out noise", ""}},
    {"gap", {"insmc gap --records runs.csv --out gap", ""}},
    {"gap-validate", {"insmc gap-validate --quick --out validation", ""}},
    {"compensate", {"insmc compensate --records unit.csv --limit horizontal@84min=3nmi --units nmi --out unit", ""}},
    {"effects", {"insmc effects --format csv", ""}},
    {"params", {"insmc params --bound gyro_drift=5meru", ""}},
    {"bench", {"insmc bench --rounds 3", ""}},
};

}  // namespace

std::span<const std::string_view> help_examples(std::string_view subcommand) {
  for (const Examples& e : kExamples)
    if (e.subcommand == subcommand) return {e.lines.data(), e.lines[1].empty() ? 1u : 2u};
  return {};
}

}  // namespace insmc::app
