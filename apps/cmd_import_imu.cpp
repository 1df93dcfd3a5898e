// insmc import-imu: raw IMU samples (CSV) → records of format v1
// (docs/records.md, docs/real-data/import.md). A strapdown computer in the
// inertial frame on a stationary base stands in for the space-stabilized
// platform (lib/imu/strapdown.h): leveling from the accelerometers, azimuth
// and latitude from the user, gyro bias from the alignment window, then test
// run and navigation.
#include <cmath>
#include <fmt/format.h>

#include "apps/cli_common.h"
#include "apps/imu_csv_options.h"
#include "apps/output_paths.h"
#include "lib/common/input_error.h"
#include "lib/common/input_text.h"
#include "lib/imu/imu_samples.h"
#include "lib/imu/strapdown.h"
#include "lib/imu/strapdown_records.h"
#include "lib/records/record_budget.h"
#include "lib/records/record_io.h"
#include "lib/units/quantity.h"
#include "montecarlo/records/gap/diagnosis.h"
#include "montecarlo/records/noise/noise_header.h"

namespace insmc::app {
namespace {

RunsFrom parse_runs_from(const std::string& text) {
  if (text == "file") return RunsFrom::kFile;
  if (text == "split") return RunsFrom::kSplit;
  throw InputError("--runs-from", echo_input(text),
                   "must be file (one run from the start of each input) or split (consecutive runs of "
                   "alignment + test + navigation from each input)");
}

}  // namespace

int cmd_import_imu(const Args& args) {
  po::options_description opts("Options");
  opts.add_options()("input", po::value<std::vector<std::string>>()->composing(),
                     "IMU CSV file (plain text; gunzip first), repeatable: runs in the given order")(
      "out", po::value<std::string>(), "record file to write (required)")(
      "runs-from", po::value<std::string>()->default_value("file"),
      "file: one run from the start of each input; split: consecutive runs of align + test + nav")(
      "latitude", po::value<std::string>(), "latitude L0 of the site (required, e.g. 51.08deg)")(
      "altitude", po::value<std::string>()->default_value("0m"), "height of the site above the model sphere r0")(
      "azimuth", po::value<std::string>()->default_value("0deg"),
      "heading of the sensor x axis from north, positive toward east (system 1's theodolite)")(
      "align-duration", po::value<std::string>()->default_value("300s"),
      "alignment window before t = 0: leveling and gyro-bias estimate")(
      "test-duration", po::value<std::string>()->default_value("15min"), "test run T after the switch to navigation")(
      "nav-duration", po::value<std::string>()->default_value("90min"), "navigation after the test run")(
      "interval", po::value<std::string>()->default_value("10s"),
      "output interval, also the filter interval tau of the accelerometer error f")(
      "gyro-bias", po::value<std::string>()->default_value("remove"),
      "remove: subtract the gyro bias estimated during alignment; keep: navigate on the raw gyros")(
      "noise", po::value<std::string>()->default_value("on"),
      "on: run the raw-sensor noise stage (insmc noise) on the inputs and keep its fitted terms in the header "
      "(imu.noise.*), where gap reads them; off: skip it");
  add_imu_csv_options(opts);
  const auto vm = parse_args(args, "import-imu",
                             "--input FILE [--input FILE]... --out FILE --latitude ANGLE (--rate RATE | "
                             "--time-column NAME) [options]",
                             opts);
  if (!vm) return 0;
  if (!vm->count("input")) throw InputError("--input", "(missing)", "give at least one IMU CSV file");
  if (!vm->count("out")) throw InputError("--out", "(missing)", "give the record file to write");
  if (!vm->count("latitude"))
    throw InputError("--latitude", "(missing)",
                     "give the site's latitude (e.g. 51.08deg): the earth rate the gyros sense and the expected "
                     "gravity depend on it");
  const auto q = [&](const char* name, Dimension d) {
    return parse_quantity((*vm)[name].as<std::string>(), d, std::string("--") + name);
  };

  const ImuCsvOptions csv = read_imu_csv_options(*vm);

  StrapdownOptions nav;
  nav.latitude_rad = q("latitude", Dimension::kAngle);
  nav.altitude_m = q("altitude", Dimension::kLength);
  nav.azimuth_rad = q("azimuth", Dimension::kAngle);
  nav.align_duration_s = q("align-duration", Dimension::kTime);
  nav.test_duration_s = q("test-duration", Dimension::kTime);
  nav.nav_duration_s = q("nav-duration", Dimension::kTime);
  nav.output_interval_s = q("interval", Dimension::kTime);
  nav.gyro_bias = parse_gyro_bias_mode((*vm)["gyro-bias"].as<std::string>(), "--gyro-bias");
  validate(nav);
  const RunsFrom runs_from = parse_runs_from((*vm)["runs-from"].as<std::string>());
  // What the record file can hold (lib/records/record.h): a run of at most
  // 48 h, a filter interval in [0.1 ms, 1 h].
  if (nav.test_duration_s + nav.nav_duration_s > kMaxRunDurationS)
    throw InputError("--nav-duration", format_quantity(nav.nav_duration_s, Dimension::kTime),
                     fmt::format("the test run and the navigation together may last at most {} h (a record's run)",
                                 kMaxRunDurationS / 3600));
  if (!(nav.output_interval_s >= kMinFilterIntervalS && nav.output_interval_s <= kMaxFilterIntervalS))
    throw InputError("--interval", format_quantity(nav.output_interval_s, Dimension::kTime),
                     fmt::format("must lie in [{}s, {}s] (a record's filter interval)", kMinFilterIntervalS,
                                 kMaxFilterIntervalS));
  // The rows of a run, a row every interval from t = 0 to T + the
  // navigation (at most), before any input is read: a file insmc writes is
  // one its readers take, within the budget (lib/records/record_budget.h).
  const std::size_t inputs_given = (*vm)["input"].as<std::vector<std::string>>().size();
  const auto check_rows = [&](std::size_t runs) {
    const double run_s = nav.test_duration_s + nav.nav_duration_s;
    const std::size_t per_run = static_cast<std::size_t>(std::floor(run_s / nav.output_interval_s)) + 2;
    const double finest_s = run_s * static_cast<double>(runs) / static_cast<double>(kMaxWrittenRecordRows - 2 * runs);
    check_written_rows("--interval", echo_input((*vm)["interval"].as<std::string>()), runs, per_run,
                       fmt::format("{} of test run and navigation at {}", format_quantity(run_s, Dimension::kTime),
                                   format_quantity(nav.output_interval_s, Dimension::kTime)),
                       2 * runs < kMaxWrittenRecordRows
                           ? fmt::format("the interval must be at least {}", format_quantity(round_up_3(finest_s), Dimension::kTime))
                           : "import fewer runs");
  };
  check_rows(inputs_given);  // at least one run per input
  const OutputFileOption out_file("--out", (*vm)["out"].as<std::string>(), input_files(*vm));  // checked and locked before the work

  RecordFile file = imported_file_header(nav, csv, runs_from);

  const std::string noise_mode = (*vm)["noise"].as<std::string>();
  if (noise_mode != "on" && noise_mode != "off") throw InputError("--noise", echo_input(noise_mode), "must be on or off");
  const std::vector<std::string> inputs = (*vm)["input"].as<std::vector<std::string>>();
  std::vector<ImuSamples> all_samples;
  for (const std::string& input : inputs) {
    all_samples.push_back(read_input("--input", input, [&] { return read_imu_csv(input, csv); }));
    if (auto e = hole_problem(all_samples.back())) throw *e;
  }
  // Only files insmc itself reads: at most the runs one diagnosis takes.
  std::size_t total_runs = 0;
  for (const ImuSamples& samples : all_samples)
    total_runs += static_cast<std::size_t>(runs_from_input(samples, nav, runs_from));
  if (total_runs > gap::kMaxDiagnosedRuns)
    throw InputError("--runs-from", runs_from == RunsFrom::kFile ? "file" : "split",
                     fmt::format("the inputs make {} runs: a record file for insmc gap holds at most {} (lengthen "
                                 "--nav-duration or --test-duration, or import fewer inputs)",
                                 total_runs, gap::kMaxDiagnosedRuns));
  check_rows(total_runs);  // the runs the inputs make (split: several an input)
  if (noise_mode == "on") noise::write_noise_header(all_samples, file.header);

  append_imported_runs(file, all_samples, inputs, nav, runs_from);
  out_file.write(write_record_file(file));
  return 0;
}

}  // namespace insmc::app
