#include "apps/imu_csv_options.h"

#include <optional>
#include <sstream>

#include "lib/common/input_error.h"
#include "lib/common/input_text.h"
#include "lib/units/quantity.h"

namespace insmc::app {
namespace {

/// "a,b,c" → three column names (blanks around names dropped).
std::array<std::string, 3> parse_three_columns(const std::string& text, const char* field) {
  std::array<std::string, 3> out;
  std::stringstream in(text);
  std::string item;
  int n = 0;
  while (std::getline(in, item, ',')) {
    const auto first = item.find_first_not_of(" \t"), last = item.find_last_not_of(" \t");
    if (n < 3) out[n] = first == std::string::npos ? "" : item.substr(first, last - first + 1);
    ++n;
  }
  if (n != 3 || (!text.empty() && text.back() == ','))
    throw InputError(field, echo_input(text), "must be three column names X,Y,Z separated by commas");
  return out;
}

}  // namespace

void add_imu_csv_options(po::options_description& opts) {
  opts.add_options()("rate", po::value<std::string>(), "sample rate, e.g. 100Hz (sample k at k/rate); or --time-column")(
      "time-column", po::value<std::string>(), "column with the sample times (instead of --rate)")(
      "time-unit", po::value<std::string>()->default_value("s"), "unit of the time column: s, ms, min, h")(
      "gyro-columns", po::value<std::string>()->default_value("gyro_x_dps,gyro_y_dps,gyro_z_dps"),
      "gyro columns of the sensor x,y,z axes")(
      "accel-columns", po::value<std::string>()->default_value("acc_x_g,acc_y_g,acc_z_g"),
      "accelerometer columns of the sensor x,y,z axes")(
      "gyro-unit", po::value<std::string>()->default_value("deg/s"), "unit of the gyro columns: deg/s, rad/s, deg/h")(
      "accel-unit", po::value<std::string>()->default_value("g"), "unit of the accelerometer columns: g, m/s2");
}

ImuCsvOptions read_imu_csv_options(const po::variables_map& vm) {
  ImuCsvOptions csv;
  csv.gyro_columns = parse_three_columns(vm["gyro-columns"].as<std::string>(), "--gyro-columns");
  csv.accel_columns = parse_three_columns(vm["accel-columns"].as<std::string>(), "--accel-columns");
  csv.gyro_unit = parse_gyro_unit(vm["gyro-unit"].as<std::string>(), "--gyro-unit");
  csv.accel_unit = parse_accel_unit(vm["accel-unit"].as<std::string>(), "--accel-unit");
  if (!vm.count("rate") && !vm.count("time-column"))
    throw InputError("--rate", "(missing)", "give the sample rate (e.g. 100Hz) or a time column with --time-column");
  if (vm.count("rate")) csv.rate_hz = parse_rate_hz(vm["rate"].as<std::string>(), "--rate");
  // The time unit is checked even without a time column: a typo is refused, not ignored.
  const std::string unit = vm["time-unit"].as<std::string>();
  // A unit alone, read whole: "0s" or "e3s" is not a unit.
  const std::optional<double> time_unit = unit_factor(unit, Dimension::kTime);
  if (!time_unit) throw InputError("--time-unit", echo_input(unit), "must be one of: s, min, h, ms");
  const double time_unit_s = *time_unit;
  if (vm.count("time-column")) {
    csv.time_column = vm["time-column"].as<std::string>();
    csv.time_unit_s = time_unit_s;
  }
  validate(csv);
  return csv;
}

}  // namespace insmc::app
