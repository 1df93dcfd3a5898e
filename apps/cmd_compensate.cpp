// insmc compensate: one unit on the flight line (docs/compensate.md). From a
// unit's recorded test run: its estimates with their uncertainty, the
// compensation each scheme would apply, the position error after each
// scheme (this unit's beside the population's), the scheme to use at the
// flight time, and go / no-go against the user's limits (exit 0 go, 1
// no-go, 2 bad input).
#include <fmt/format.h>

#include <algorithm>

#include "apps/cli_common.h"
#include "apps/report_output.h"
#include "apps/study_options.h"
#include "lib/common/input_error.h"
#include "lib/common/input_text.h"
#include "lib/preflight/test_run.h"
#include "lib/records/record_io.h"
#include "lib/units/physical_range.h"
#include "montecarlo/records/compensate/compensate_report.h"

namespace insmc::app {
namespace {

/// Runs of one call: each costs a model per scheme (about a second); a
/// flight line checks a few units at a time.
constexpr std::size_t kMaxUnits = 100;
constexpr std::size_t kMaxLimits = 20;

compensate::PositionLimit parse_limit(const std::string& text) {
  const std::string allowed =
      "COMPONENT@TIME=LENGTH, COMPONENT horizontal, x, y or z, TIME in (0, 12h], LENGTH in (0, 40000 km] (e.g. horizontal@84min=3nmi)";
  const auto at = text.find('@'), eq = text.find('=');
  if (at == std::string::npos || eq == std::string::npos || eq < at) throw InputError("--limit", echo_input(text), allowed);
  compensate::PositionLimit l;
  l.text = text;
  const std::string component = text.substr(0, at);
  if (component == "horizontal") l.component = compensate::PositionLimit::Component::kHorizontal;
  else if (component == "x") l.component = compensate::PositionLimit::Component::kX;
  else if (component == "y") l.component = compensate::PositionLimit::Component::kY;
  else if (component == "z") l.component = compensate::PositionLimit::Component::kZ;
  else throw InputError("--limit", echo_input(text), allowed);
  l.t_s = parse_quantity(std::string_view(text).substr(at + 1, eq - at - 1), Dimension::kTime, "--limit");
  l.limit_m = parse_quantity(std::string_view(text).substr(eq + 1), Dimension::kLength, "--limit");
  if (!(l.t_s > 0 && l.t_s <= compensate::kMaxFlightTimeS) || !kPositionLimitRange.contains(l.limit_m))
    throw InputError("--limit", echo_input(text), allowed);
  return l;
}

std::vector<Scheme> parse_schemes(const std::string& text) {
  if (text == "all") return all_schemes();
  std::vector<Scheme> out;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t comma = std::min(text.find(',', start), text.size());
    const Scheme s = parse_scheme(std::string_view(text).substr(start, comma - start), "--scheme");
    if (std::find(out.begin(), out.end(), s) == out.end()) out.push_back(s);
    start = comma + 1;
  }
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace

int cmd_compensate(const Args& args) {
  po::options_description opts("Options");
  opts.add_options()("records", po::value<std::string>(), "record file (format v1) holding the unit's test run")(
      "run", po::value<long long>(), "the run (its id) to take; default every run, each a unit")(
      "scheme", po::value<std::string>()->default_value("all"), "all, or schemes separated by commas (5.1.2,5.4)")(
      "flight-time", po::value<std::string>()->default_value("84min"),
      "time of flight on each scheme's clock, at which the scheme to use is chosen, in (0, 12h]")(
      "limit", po::value<std::vector<std::string>>()->composing(),
      "a limit on the position error after the chosen scheme, COMPONENT@TIME=LENGTH (horizontal@84min=3nmi), "
      "repeatable")(
      "risk", po::value<double>()->default_value(0.01),
      "go when each limit is exceeded with probability at most this, in (0, 0.5]")(
      "site-gravity", po::value<std::string>(),
      "the specific force at the site (its surveyed gravity), e.g. 9.8062mps2, in [9.7, 9.9] m/s^2; default the "
      "report's g = 9.80665 m/s^2 (a site's differs by up to 0.3 %, which the finest estimates resolve)")(
      "realignment-duration", po::value<std::string>()->default_value("600s"),
      "duration of the realignment of 5.1.1, 5.1.2 and combined, in [0, 6h]")(
      "out", po::value<std::string>(), out_folder_help(compensate::compensate_report_outline()).c_str())(
      "format", po::value<std::string>()->default_value("markdown"),
      "stdout: markdown (compensate.md), csv (envelope.csv) or json (compensate.json)")(
      "units", po::value<std::string>()->default_value("si"),
      "lengths of the roll-up and the verdicts: si (metres), paper (feet) or nmi (nautical miles); the CSV and "
      "JSON stay in metres (_m)");
  opts.add(uncertainty_options_description());
  const auto vm = parse_args(args, "compensate", "--records FILE [--run ID] [--limit horizontal@84min=3nmi] [options]", opts);
  if (!vm) return 0;
  if (!vm->count("records")) throw InputError("--records", "(missing)", "give the record file of the unit's test run");
  const mc::ReportOutline outline = compensate::compensate_report_outline();
  const mc::ReportFormat format = read_report_format(*vm, outline);
  compensate::CompensateOptions options;
  options.prior = read_uncertainty_model(*vm);
  options.schemes = parse_schemes((*vm)["scheme"].as<std::string>());
  options.flight_time_s = parse_quantity((*vm)["flight-time"].as<std::string>(), Dimension::kTime, "--flight-time");
  if (vm->count("limit")) {
    const auto texts = (*vm)["limit"].as<std::vector<std::string>>();
    if (texts.size() > kMaxLimits)
      throw InputError("--limit", fmt::format("({} limits)", texts.size()), fmt::format("at most {}", kMaxLimits));
    for (const std::string& t : texts) options.limits.push_back(parse_limit(t));
  }
  options.units = read_length_unit(*vm);
  options.risk = (*vm)["risk"].as<double>();
  options.realignment_duration_s =
      parse_quantity((*vm)["realignment-duration"].as<std::string>(), Dimension::kTime, "--realignment-duration");
  if (vm->count("run")) options.run = (*vm)["run"].as<long long>();
  if (vm->count("site-gravity"))
    options.site_gravity_mps2 =
        parse_quantity((*vm)["site-gravity"].as<std::string>(), Dimension::kAcceleration, "--site-gravity");
  compensate::validate(options);
  std::optional<OutputFolderOption> out = prepare_report_folder(*vm, outline);

  const std::string name = (*vm)["records"].as<std::string>();
  const RecordFile file = read_input("--records", name, [&] { return read_record_file(name); });
  const std::size_t units = options.run ? 1 : file.runs.size();
  if (units > kMaxUnits)
    throw InputError("--records", echo_input(name, 256),
                     fmt::format("{} runs: compensate takes at most {} units at a time (choose one with --run)", units,
                                 kMaxUnits));
  // What the rows of a run lack (a hole in the test grid, a scheme) is
  // said of this file: the reader's own errors name file:line:column.
  const compensate::CompensateResult result = [&] {
    try {
      return compensate::compensate(file, options);
    } catch (const InputError& e) {
      if (e.field().empty() || e.field().starts_with("--")) throw;
      throw InputError(name + ": " + e.field(), e.value(), e.allowed());
    }
  }();
  write_report(compensate::compensate_report(result, options, name), {format}, out, *vm);
  return result.all_go() ? 0 : 1;
}

}  // namespace insmc::app
