#include "apps/cli_common.h"

#include <charconv>
#include <cmath>
#include <fmt/core.h>
#include <fstream>
#include <iostream>
#include <set>

#include "apps/config_options.h"
#include "apps/help_examples.h"
#include "apps/sweep.h"
#include "lib/common/closest_name.h"
#include "lib/common/input_error.h"
#include "lib/common/input_text.h"
#include "lib/units/physical_range.h"
#include "lib/units/quantity.h"
#include "lib/units/units.h"

namespace insmc::app {

namespace {

/// The options of a subcommand with the --help and --config every one takes.
po::options_description with_generic(const po::options_description& options) {
  po::options_description generic("General");
  generic.add_options()("help,h", "print this help and exit")(
      "config", po::value<std::string>(),
      "INI file with the options that define the study (and --format, --units, --quiet, --full, --threads) as "
      "key = value; the command line wins");
  po::options_description all;
  all.add(options).add(generic);
  return all;
}

po::variables_map store_all(const Args& args, const po::options_description& all) {
  po::variables_map vm;
  po::store(po::command_line_parser(args).options(all).run(), vm);
  if (vm.count("config")) store_config_file(vm["config"].as<std::string>(), all, vm);
  po::notify(vm);
  return vm;
}

}  // namespace

std::optional<po::variables_map> parse_args(const Args& args, const std::string& subcommand,
                                            const std::string& synopsis, const po::options_description& options,
                                            Lists lists) {
  const po::options_description all = with_generic(options);
  {
    po::variables_map first;
    try {
      po::store(po::command_line_parser(args).options(all).run(), first);
    } catch (const po::unknown_option& e) {
      // A '%' in it: parse_error_message's own line (Boost's placeholders).
      if (e.get_option_name().find('%') != std::string::npos) throw;
      std::vector<std::string> names;
      for (const auto& o : all.options()) names.push_back("--" + o->long_name());
      throw po::error("unrecognised option '" + echo_input(e.get_option_name()) + "'" +
                      did_you_mean(e.get_option_name(), names));
    }
    if (first.count("help")) {
      fmt::print("usage: insmc {} {}\n\n", subcommand, synopsis);
      std::cout << all;
      const auto examples = help_examples(subcommand);
      if (!examples.empty()) std::cout << "\nExample" << (examples.size() > 1 ? "s" : "") << ":\n";
      for (std::string_view line : examples) std::cout << "  " << line << "\n";
      std::cout << std::flush;
      return std::nullopt;
    }
  }
  po::variables_map vm = store_all(args, all);
  if (lists == Lists::kOneValue) refuse_sweeps(vm, subcommand);
  return vm;
}

po::variables_map parse_args_with_file(const Args& args, const std::string& own, const po::parsed_options& kept,
                                       const po::options_description& options, const std::vector<po::option>& added) {
  const po::options_description all = with_generic(options);
  po::parsed_options typed(&all), from_file(&all);
  std::set<std::string> given;
  for (const po::option& o : po::command_line_parser(args).options(all).run().options) {
    if (o.string_key == own) continue;
    given.insert(o.string_key);
    typed.options.push_back(o);
  }
  for (const po::option& o : added) {
    given.insert(o.string_key);
    typed.options.push_back(o);
  }
  for (const po::option& o : kept.options)
    if (!given.count(o.string_key)) from_file.options.push_back(o);
  po::variables_map vm;
  po::store(typed, vm);
  po::store(from_file, vm);
  if (vm.count("config")) store_config_file(vm["config"].as<std::string>(), all, vm);
  po::notify(vm);
  // The file cannot hold --help (apps/option_sources.h); one typed beside
  // --from or --resume was answered by the first parse.
  if (vm.count("help")) throw InputError("--help", "(with the options of a file)", "cannot be combined with them");
  return vm;
}

/// A count as an integer ("100000") or in exponent form when that is a
/// whole number ("1e5", "2.5e6"), up to 2^53 in that form (every integer
/// there is exact in a double).
std::uint64_t parse_count(const std::string& text, const std::string& field) {
  const char* end = text.data() + text.size();
  std::uint64_t v = 0;
  if (const auto [ptr, ec] = std::from_chars(text.data(), end, v); ec == std::errc() && ptr == end) return v;
  double x = 0;
  const auto [ptr, ec] = std::from_chars(text.data(), end, x);
  const bool whole = ec == std::errc() && ptr == end && x >= 0 && x == std::floor(x);
  if (whole && x <= 0x1p53) return static_cast<std::uint64_t>(x);
  throw InputError(field, echo_input(text), whole || ec == std::errc::result_out_of_range
      ? "is too large: a whole number up to 2^53 (9007199254740992) in exponent form, or 18446744073709551615 in digits"
      : "must be a non-negative whole number (e.g. 100000 or 1e5)");
}

std::uint64_t read_count(const po::variables_map& vm, const std::string& name) {
  return parse_count(vm[name].as<std::string>(), "--" + name);
}

gap::RecordWriter read_record_writer(const po::variables_map& vm) {
  const std::string& text = vm["layout"].as<std::string>();
  if (text == "own") return gap::RecordWriter::kOwn;
  if (text == "foreign") return gap::RecordWriter::kForeign;
  if (text == "fuzzed") return gap::RecordWriter::kFuzzed;
  throw InputError("--layout", text, "must be own, foreign or fuzzed");
}

po::options_description model_options_description() {
  po::options_description d("Model");
  d.add_options()("latitude", po::value<std::string>()->default_value("45deg"),
                  "latitude L0 of the stationary vehicle (e.g. 45deg, 0.7854rad)")(
      "leveling-gain", po::value<double>()->default_value(500.0),
      "system-1 leveling-loop DC gain F(0) in units of earth rate (§2.1), in [10, 1e5]");
  return d;
}

ModelOptions read_model_options(const po::variables_map& vm, bool system2_used) {
  ModelOptions o;
  const std::string lat_option = vm["latitude"].as<std::string>();
  const std::string lat = lat_option.substr(0, lat_option.find(','));  // a comma list is a sweep
  o.latitude_rad = parse_quantity(lat, Dimension::kAngle, "--latitude");
  const double abs_lat = std::abs(o.latitude_rad);
  if (system2_used && !(abs_lat < 90.0 * kDegToRad - 1e-9)) {
    throw InputError("--latitude", lat,
                     "must lie strictly between -90deg and 90deg for system 2: gyrocompassing "
                     "divides by cos L0 (2.16)");
  }
  if (!(abs_lat <= 90.0 * kDegToRad)) throw InputError("--latitude", lat, "must lie within ±90deg");
  o.leveling_gain_ratio = vm["leveling-gain"].as<double>();
  require_in_range("--leveling-gain", o.leveling_gain_ratio, Dimension::kDimensionless,
                   {ModelOptions::kMinLevelingGainRatio, ModelOptions::kMaxLevelingGainRatio}, "F(0)/ω_ie");
  return o;
}

}  // namespace insmc::app
