#pragma once
/// The subcommands of `insmc`, one file each (apps/cmd_<name>.cpp). Each
/// takes the arguments after its name and returns the exit code: 0 success,
/// 1 a `check` bound violated, 2 bad input (via InputError, caught in main).
#include <string>
#include <vector>

namespace insmc::app {

using Args = std::vector<std::string>;

int cmd_params(const Args& args);
int cmd_tables(const Args& args);
int cmd_run(const Args& args);
int cmd_covariance(const Args& args);
int cmd_rank(const Args& args);
int cmd_check(const Args& args);
int cmd_bench(const Args& args);
int cmd_effects(const Args& args);
int cmd_simulate(const Args& args);
int cmd_gap(const Args& args);
int cmd_gap_validate(const Args& args);
int cmd_import_imu(const Args& args);
int cmd_noise(const Args& args);
int cmd_compensate(const Args& args);

}  // namespace insmc::app
