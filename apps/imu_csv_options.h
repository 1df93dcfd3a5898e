#pragma once
// The options that say how to read raw IMU CSV files, shared by `import-imu`
// and `noise`: columns, units, sample rate or time column.
#include <boost/program_options.hpp>

#include "lib/imu/imu_samples.h"

namespace insmc::app {

namespace po = boost::program_options;

/// Adds --rate, --time-column, --time-unit, --gyro-columns, --accel-columns,
/// --gyro-unit, --accel-unit.
void add_imu_csv_options(po::options_description& opts);
/// Reads and validates them (InputError naming the option on bad input).
ImuCsvOptions read_imu_csv_options(const po::variables_map& vm);

}  // namespace insmc::app
