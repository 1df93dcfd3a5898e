#pragma once
/// The subcommands of `insmc`, one file each (apps/cmd_<name>.cpp). Each
/// takes the arguments after its name and returns the exit code: 0 success,
/// 1 a `check` bound violated, 2 bad input (via InputError, caught in main).
#include <string>
#include <vector>

namespace insmc::app {

using Args = std::vector<std::string>;

int run_params(const Args& args);
int run_tables(const Args& args);
int run_run(const Args& args);
int run_covariance(const Args& args);
int run_rank(const Args& args);
int run_check(const Args& args);
int run_bench(const Args& args);
int run_effects(const Args& args);
int run_simulate(const Args& args);
int run_gap(const Args& args);
int run_gap_validate(const Args& args);
int run_import_imu(const Args& args);
int run_noise(const Args& args);
int run_compensate(const Args& args);

}  // namespace insmc::app
