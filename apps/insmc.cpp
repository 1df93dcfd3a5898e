// insmc: the subcommands (one file each, apps/cmd_<name>.cpp) and main;
// apps/dispatch.h finds the one named and turns its failures into one line
// on stderr and an exit code.
#include <malloc.h>

#include "apps/dispatch.h"

namespace {

constexpr insmc::app::Subcommand kSubcommands[] = {
    {"run", insmc::app::cmd_run, "Monte Carlo study: RMS position-error envelopes with confidence intervals"},
    {"covariance", insmc::app::cmd_covariance, "exact linear-covariance envelopes and the error budget"},
    {"rank", insmc::app::cmd_rank, "the schemes in order with its significance, and the break-even assumptions"},
    {"check", insmc::app::cmd_check, "statistical bounds for CI: exit 1 when a bound is violated"},
    {"tables", insmc::app::cmd_tables, "the report's tables beside the values insmc computes"},
    {"simulate", insmc::app::cmd_simulate, "truth-level records (format v1) with chosen named effects"},
    {"import-imu", insmc::app::cmd_import_imu, "records (format v1) from raw IMU samples: strapdown, stationary base"},
    {"noise", insmc::app::cmd_noise, "raw-sensor noise: Allan deviation, fitted noise terms, warm-up, disturbances"},
    {"gap", insmc::app::cmd_gap, "sim-to-real gap diagnosis of record files: where, which effect, how far it shrinks"},
    {"gap-validate", insmc::app::cmd_gap_validate, "the gap diagnosis scored blind on records with withheld effects"},
    {"compensate", insmc::app::cmd_compensate, "one unit from its test run: estimates, each scheme's envelope, go / no-go"},
    {"effects", insmc::app::cmd_effects, "the truth simulator's named effects, parameters and defaults"},
    {"params", insmc::app::cmd_params, "the uncertainty catalogue: names, symbols, units, bounds"},
    {"bench", insmc::app::cmd_bench, "throughput of the Monte Carlo paths against the machine's floor"},
};

}  // namespace

int main(int argc, char** argv) {
  // The gap diagnosis allocates and frees matrices of a few MB per grid
  // point on every thread; by default glibc hands such blocks back to the
  // kernel and faults them in again (measured: a third of gap-validate's
  // wall time in page faults). Keep them in the heap instead.
  mallopt(M_MMAP_THRESHOLD, 256 << 20);
  mallopt(M_TRIM_THRESHOLD, 512 << 20);
  return insmc::app::dispatch(kSubcommands, argc, argv);
}
