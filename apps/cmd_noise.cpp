// insmc noise: the raw-sensor noise stage (docs/noise.md). Overlapping Allan
// deviation of each gyro and accelerometer channel with its intervals, the
// standard noise terms fitted with intervals and selected, disturbances
// masked, the warm-up tested, all beside Table 3.1's bounds.
#include <fmt/format.h>

#include "apps/cli_common.h"
#include "apps/imu_csv_options.h"
#include "apps/progress.h"
#include "apps/report_output.h"
#include "lib/common/input_error.h"
#include "lib/common/input_text.h"
#include "lib/noise/noise_analysis.h"
#include "lib/units/physical_range.h"
#include "lib/units/quantity.h"
#include "montecarlo/records/noise/noise_report.h"

namespace insmc::app {

using noise::parse_datasheet_entry;

int cmd_noise(const Args& args) {
  po::options_description opts("Options");
  opts.add_options()("input", po::value<std::vector<std::string>>()->composing(),
                     "IMU CSV file of a static recording (plain text), repeatable: one recording each")(
      "out", po::value<std::string>(), out_folder_help(noise::noise_report_outline()).c_str())(
      "format", po::value<std::string>()->default_value("markdown"), "what to print: markdown or json")(
      "alpha", po::value<double>()->default_value(0.01, "0.01"),
      "family-wise level of the masking, the stationarity test and the term selection, in [1e-6, 0.2]")(
      "confidence", po::value<double>()->default_value(0.95, "0.95"), "of every interval, in [0.5, 0.999999]")(
      "first-part", po::value<std::string>()->default_value("1h"),
      "start of each recording tested against the rest (warm-up); at most half the longest recording is used; 0s: no test")(
      "mask", po::value<std::string>()->default_value("on"), "on: mask disturbances; off: use every sample")(
      "datasheet", po::value<std::vector<std::string>>()->composing(),
      "a data-sheet value to draw on the allan figure and compare with the fit, repeatable: gyro_arw=0.15degprth, "
      "gyro_bias_instability=1degph, accel_vrw=0.03mpsprth, accel_bias_instability=50ug")(
      "gravity", po::value<std::string>()->default_value("9.80665mps2"),
      "the site's gravity magnitude, the reference of a multi-position calibration, in [9.7, 9.9] m/s2");
  add_imu_csv_options(opts);
  const auto vm = parse_args(args, "noise", "--input FILE [--input FILE]... (--rate RATE | --time-column NAME) [options]", opts);
  if (!vm) return 0;
  if (!vm->count("input")) throw InputError("--input", "(missing)", "give at least one IMU CSV file");
  const ImuCsvOptions csv = read_imu_csv_options(*vm);
  noise::NoiseStageOptions stage;
  noise::NoiseOptions& options = stage.analysis;
  options.alpha = (*vm)["alpha"].as<double>();
  if (!(options.alpha >= 1e-6 && options.alpha <= 0.2))
    throw InputError("--alpha", fmt::format("{:g}", options.alpha), "must lie in [1e-6, 0.2]");
  options.confidence = (*vm)["confidence"].as<double>();
  if (!(options.confidence >= 0.5 && options.confidence <= 0.999999))
    throw InputError("--confidence", fmt::format("{:g}", options.confidence), "must lie in [0.5, 0.999999]");
  options.first_part_s = parse_quantity((*vm)["first-part"].as<std::string>(), Dimension::kTime, "--first-part");
  if (!(options.first_part_s == 0 || (options.first_part_s >= 60 && options.first_part_s <= 86400)))
    throw InputError("--first-part", echo_input((*vm)["first-part"].as<std::string>()),
                     "must be 0s (no warm-up test) or lie in [1min, 24h]");
  const std::string mask = (*vm)["mask"].as<std::string>();
  if (mask != "on" && mask != "off") throw InputError("--mask", echo_input(mask), "must be on or off");
  if (vm->count("datasheet"))
    for (const std::string& entry : (*vm)["datasheet"].as<std::vector<std::string>>())
      parse_datasheet_entry(entry, stage.sheet);
  options.mask = mask == "on";
  const mc::ReportOutline outline = noise::noise_report_outline();
  const mc::ReportFormat format = read_report_format(*vm, outline);
  calibration::MultipositionOptions& calibrate = stage.calibration;
  calibrate.confidence = options.confidence;
  const std::string gravity_text = (*vm)["gravity"].as<std::string>();
  calibrate.gravity_mps2 = parse_quantity(gravity_text, Dimension::kAcceleration, "--gravity");
  // Said in m/s², the unit gravity is quoted in.
  if (!kSiteGravityRange.contains(calibrate.gravity_mps2))
    throw InputError("--gravity", echo_input(gravity_text),
                     "must lie in [9.7, 9.9] m/s2 (surface gravity, equator to poles, with room for altitude), "
                     "e.g. 9.80665mps2");
  std::optional<OutputFolderOption> out = prepare_report_folder(*vm, outline);

  std::vector<ImuSamples> recordings;
  for (const std::string& input : (*vm)["input"].as<std::vector<std::string>>()) {
    recordings.push_back(read_input("--input", input, [&] { return read_imu_csv(input, csv); }));
    noise::require_noise_samples(recordings.back());  // before the next file is read
  }
  const mc::Report report = [&] {  // the progress line ends before stdout
    Progress progress(0, "");
    options.progress = [&progress](std::string_view what, std::size_t done, std::size_t total) {
      progress.update(what, done, total, "channels");
    };
    mc::Report done = noise::noise_stage(std::move(recordings), stage);
    options.progress = nullptr;
    return done;
  }();
  write_report(report, {format}, out, *vm);
  return 0;
}

}  // namespace insmc::app
