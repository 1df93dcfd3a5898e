// insmc simulate: truth-level records (record format v1, docs/records.md) of
// runs on a stationary base: switch-over, test run, navigation, with chosen
// named effects. Runs are deterministic per (seed, run).
#include <algorithm>
#include <cmath>
#include <optional>
#include <fmt/format.h>

#include "apps/cli_common.h"
#include "apps/output_paths.h"
#include "apps/study_options.h"
#include "lib/common/assert.h"
#include "lib/common/input_error.h"
#include "lib/common/input_text.h"
#include "lib/records/record_budget.h"
#include "lib/records/record_io.h"
#include "lib/compensation/truth_compensation.h"
#include "lib/truth/simulator.h"
#include "lib/units/quantity.h"
#include "lib/units/units.h"
#include "montecarlo/records/runs/simulation/record_simulation.h"
#include "montecarlo/records/gap/diagnosis_options.h"
#include "montecarlo/records/gap/validation/writer_conventions.h"
#include "montecarlo/study/sampler/sampler.h"

namespace insmc::app {
namespace {

bool needs_pulses(const TruthOptions& truth) {
  return std::any_of(truth.effects.begin(), truth.effects.end(),
                     [](const EffectSpec& e) { return e.kind.info().needs_pulses; });
}

/// The rows the file will hold, from the options alone (before any run is
/// simulated), within what a writer may write (lib/records/record_budget.h).
/// Own layout: a row every filter interval through the test run and the
/// navigation; foreign: the union of its f and r lattices, at most.
void check_simulated_rows(const po::variables_map& vm, int runs, const TestRunOptions& test, double nav_s,
                          const std::optional<gap::WriterConventions>& foreign) {
  const double T = test.duration_s, tau = test.filter_interval_s;
  const std::size_t per_run =
      foreign ? static_cast<std::size_t>(std::floor((T + nav_s) / foreign->f_every_s) +
                                         std::floor((T + nav_s) / foreign->r_every_s)) + 2
              : uniform_times(T, tau, false).size() + uniform_times(nav_s, tau, false).size();
  const std::string what =
      fmt::format("{} of test run and {} of navigation {}", format_quantity(T, Dimension::kTime),
                  format_quantity(nav_s, Dimension::kTime),
                  foreign ? fmt::format("with f every {} and r every {}", format_quantity(foreign->f_every_s, Dimension::kTime),
                                        format_quantity(foreign->r_every_s, Dimension::kTime))
                          : fmt::format("at {}", format_quantity(tau, Dimension::kTime)));
  if (per_run <= kMaxWrittenRecordRows) {
    check_written_rows("--runs", std::to_string(runs), static_cast<std::size_t>(runs), per_run, what,
                       fmt::format("at most {} runs fit", kMaxWrittenRecordRows / per_run));
    return;
  }
  // One run alone is too long: the interval or the navigation must change.
  if (foreign)
    check_written_rows("--nav-duration", format_quantity(nav_s, Dimension::kTime), 1, per_run, what,
                       "shorten the navigation");
  const double shortest_s = (T + nav_s) / static_cast<double>(kMaxWrittenRecordRows - 2);
  check_written_rows("--filter-interval", echo_input(vm["filter-interval"].as<std::string>()), 1, per_run, what, fmt::format("the filter interval must be at least {}",
                                                   format_quantity(round_up_3(shortest_s), Dimension::kTime)));
}

}  // namespace

int cmd_simulate(const Args& args) {
  po::options_description opts("Options");
  opts.add_options()("out", po::value<std::string>(), "record file to write (required)")(
      "runs", po::value<int>()->default_value(20), "number of runs (alignment, test run, navigation), 1 to 200 (the runs one gap diagnosis takes)")(
      "seed", po::value<std::string>()->default_value("1"), "seed; run i is a pure function of (seed, i)")(
      "system", po::value<std::string>()->default_value("1"), "alignment system: 1 or 2")(
      "scheme", po::value<std::string>()->default_value("none"), "compensation scheme (none: uncompensated)")(
      "nav-duration", po::value<std::string>()->default_value("90min"), "navigation after the test run")(
      "effect", po::value<std::vector<std::string>>()->composing(),
      "NAME or NAME:param=value,... (insmc effects), repeatable")(
      "step", po::value<std::string>()->default_value("5s"), "largest integration step")(
      "layout", po::value<std::string>()->default_value("own"),
      "own, or foreign: the runs written as another recorder would (f every 5, 10 or 20 s and r every 10, 30 or "
      "60 s by the seed, a third of the runs stopping 60-80 min into the navigation, other run numbers and header "
      "keys, no pulse-weight, filter-interval or resolution key, no truth keys; scheme none), or fuzzed: conventions "
      "drawn at random from the seed (f and r every 1-60 s, each run's own dropouts up to 10 %, f after the test or "
      "not, r resolution 0.1 mm to 3 ft, short runs, optional header keys or not; scheme none; docs/gap-method.md "
      "section 5)");
  opts.add(model_options_description());
  opts.add(test_run_options_description());
  opts.add(uncertainty_options_description());
  const auto vm = parse_args(args, "simulate", "--out FILE [--runs N] [--effect NAME[:p=v,...]]... [options]", opts);
  if (!vm) return 0;
  if (!vm->count("out")) throw InputError("--out", "(missing)", "give the record file to write");
  const int runs = (*vm)["runs"].as<int>();
  // Every file simulate writes can be read back by every command that reads
  // records: the diagnosis takes the fewest runs (the record reader 10,000).
  static_assert(gap::kMaxDiagnosedRuns <= kMaxRecordRuns);
  if (runs < 1 || static_cast<std::size_t>(runs) > gap::kMaxDiagnosedRuns)
    throw InputError("--runs", std::to_string(runs),
                     fmt::format("must lie in [1, {}]: a record file for insmc gap holds at most {} runs",
                                 gap::kMaxDiagnosedRuns, gap::kMaxDiagnosedRuns));
  const std::uint64_t seed = read_count(*vm, "seed");
  const System system = parse_system((*vm)["system"].as<std::string>(), "--system");
  const Scheme scheme = parse_scheme((*vm)["scheme"].as<std::string>());
  const ModelOptions model = read_model_options(*vm, system == System::kGyrocompass);
  const TestRunOptions test = read_test_run_options(*vm);
  const UncertaintyModel uncertainties = read_uncertainty_model(*vm);
  const double nav_s = parse_quantity((*vm)["nav-duration"].as<std::string>(), Dimension::kTime, "--nav-duration");
  if (!(nav_s > 0) || nav_s > 6 * 3600.0) throw InputError("--nav-duration", format_quantity(nav_s, Dimension::kTime), "must lie in (0, 6h]");

  TruthOptions truth;
  truth.model = model;
  truth.system = system;
  truth.dv_pulse_mps = test.dv_pulse_mps;
  truth.filter_interval_s = test.filter_interval_s;
  truth.alignment_loops = test.alignment_loops;
  truth.step_s = parse_quantity((*vm)["step"].as<std::string>(), Dimension::kTime, "--step");
  if (vm->count("effect"))
    for (const auto& e : (*vm)["effect"].as<std::vector<std::string>>()) truth.effects.push_back(parse_effect(e, "--effect"));
  if (const auto err = truth_latitude_error(model.latitude_rad, "--latitude")) throw *err;
  validate(truth);
  const gap::RecordWriter writer = read_record_writer(*vm);
  const bool foreign = writer != gap::RecordWriter::kOwn;
  if (foreign && scheme != Scheme::kNone)
    throw InputError("--layout", (*vm)["layout"].as<std::string>(), "writes the runs without a scheme; give --scheme none");
  const std::optional<gap::WriterConventions> conventions =
      writer == gap::RecordWriter::kFuzzed  ? std::optional(gap::fuzzed_conventions_of(seed, needs_pulses(truth), test.duration_s))
      : writer == gap::RecordWriter::kForeign ? std::optional(gap::foreign_conventions_of(seed, needs_pulses(truth)))
                                              : std::nullopt;
  check_simulated_rows(*vm, runs, test, nav_s, conventions);
  const OutputFileOption out("--out", (*vm)["out"].as<std::string>(), input_files(*vm));  // checked and locked before the work
  if (foreign) {
    gap::ForeignRuns spec;
    spec.test_duration_s = test.duration_s;
    spec.nav_duration_s = nav_s;
    spec.position_resolution_m = test.position_resolution_m;
    spec.runs = runs;
    out.write(write_record_file(gap::simulate_foreign_file(truth, mc::Sampler(uncertainties), seed, spec, *conventions)));
    return 0;
  }
  // The scheme's estimators: the same resolvable terms as `insmc run` fits.
  const Resolvability resolvable = resolvable_terms(system, model, test, uncertainties);
  const TruthSchemeSetup setup(truth, test, make_estimators(test, model, resolvable.u3, resolvable.u4));

  runs::OwnFileSpec spec;
  spec.runs = runs;
  spec.test_duration_s = test.duration_s;
  spec.nav_duration_s = nav_s;
  spec.position_resolution_m = test.position_resolution_m;
  spec.scheme = scheme;
  spec.setup = &setup;
  spec.realignment_duration_s = test.realignment_duration_s;
  out.write(write_record_file(runs::simulate_own_file(truth, mc::Sampler(uncertainties), seed, spec)));
  return 0;
}

}  // namespace insmc::app
