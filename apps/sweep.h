#pragma once
/// Trade-study sweeps on the command line: any option given a comma list
/// (--test-duration 5min,10min,15min, --bound gyro_drift=1meru,3meru,10meru,
/// --realignment-duration 5min,15min, ...) is a swept quantity; several
/// sweep over their Cartesian product. Each point is a full study
/// (montecarlo/study/run/sweep_study.h).
#include <string>
#include <vector>

#include "apps/cli_common.h"
#include "montecarlo/study/run/sweep_study.h"

namespace insmc::app {

using mc::SweepAxis;

/// The swept quantities of the command line (empty: no sweep).
std::vector<SweepAxis> find_sweeps(const po::variables_map& vm);

/// For the subcommands that take one value of each quantity: a comma list
/// in a sweepable option is refused (InputError) instead of its first value
/// being used.
void refuse_sweeps(const po::variables_map& vm, const std::string& subcommand);

}  // namespace insmc::app
