#include "apps/study_options.h"

#include "lib/uncertainty/random_fraction.h"
#include "lib/units/physical_range.h"
#include "lib/units/quantity.h"

namespace insmc::app {

po::options_description uncertainty_options_description() {
  po::options_description d("Uncertainties (names: insmc params)");
  d.add_options()("bound", po::value<std::vector<std::string>>()->composing(),
                  "NAME=VALUE with unit, e.g. gyro_drift=3meru, accel_bias_x=0.5mg; NAME is a "
                  "catalogue name, a group or all; repeatable. Physical ranges: angles 100mrad, rates 10000meru, "
                  "accelerations 100mg, velocities 10mps, scale factors 0.1, altitude 10km")(
      "dist", po::value<std::vector<std::string>>()->composing(),
      "NAME=uniform|normal:K|fixed:VALUE|zero (bound = K sigma for normal); repeatable, applied "
      "in order, e.g. --dist all=zero --dist gyro_drift_z=fixed:10meru")(
      "random-fraction", po::value<std::string>()->default_value("0.5"),
      "share of Table 3.1's zeta (1 mrad) and df (0.1 mg) drawn anew at each alignment (misalign_align, "
      "bias_change_align), the rest constant (misalign_const, bias_change_const), in [0, 1]; a comma list is a "
      "sweep; --bound on those names wins");
  return d;
}

double parse_random_fraction(const std::string& text) {
  const double f = parse_quantity(text, Dimension::kDimensionless, "--random-fraction");
  require_in_range("--random-fraction", f, Dimension::kDimensionless, {0.0, 1.0});
  return f;
}

UncertaintyModel read_uncertainty_model(const po::variables_map& vm) {
  UncertaintyModel model;
  if (vm.count("random-fraction"))  // a comma list is a sweep: its first value
    apply_random_fraction(model, parse_random_fraction(split_commas(vm["random-fraction"].as<std::string>()).front()));
  if (vm.count("bound"))
    for (const auto& a : vm["bound"].as<std::vector<std::string>>()) model.apply_bound(a);
  if (vm.count("dist"))
    for (const auto& a : vm["dist"].as<std::vector<std::string>>()) model.apply_dist(a);
  return model;
}

}  // namespace insmc::app

#include <charconv>
#include <cmath>
#include <fmt/format.h>

#include "lib/common/input_error.h"
#include "lib/common/input_text.h"
#include "lib/units/quantity.h"

namespace insmc::app {
void refuse_truth_level_options(const po::variables_map& vm, const std::string& command,
                                const std::string& why_not_truth) {
  if (vm["fidelity"].as<std::string>() == "truth") throw InputError("--fidelity", "truth", why_not_truth);
  for (const char* name : {"alignment-time", "coarse-misalignment"})
    if (!vm[name].defaulted())
      throw InputError(std::string("--") + name, vm[name].as<std::string>(),
                       "not used by " + command +
                           " (the steady-state alignment of the paper and linear levels); use insmc run --fidelity truth");
}

std::vector<std::string> split_commas(const std::string& text) {
  std::vector<std::string> out;
  std::string cur;
  for (char ch : text) {
    if (ch == ',') {
      out.push_back(cur);
      cur.clear();
    } else if (ch != ' ') {
      cur += ch;
    }
  }
  out.push_back(cur);
  return out;
}

po::options_description study_options_description(bool monte_carlo) {
  po::options_description d("Study");
  d.add_options()("system", po::value<std::string>()->default_value("1,2"),
                  "alignment system(s): 1 (theodolite), 2 (gyrocompassing), or 1,2")(
      "scheme", po::value<std::string>()->default_value("all"), "compensation scheme(s), comma list, or all")(
      "fidelity", po::value<std::string>()->default_value("linear"),
      "paper (the report's closed forms as printed), linear (full linear model, report errors corrected) or "
      "truth (the nonlinear simulator per sample, every scheme through its injection points)")(
      "confidence", po::value<double>()->default_value(0.95, "0.95"), "confidence level of the RMS intervals, in [0.5, 0.999999]")(
      "units", po::value<std::string>()->default_value("si"), "si (metres, _m columns), paper (feet, _ft columns) or nmi (nautical miles, _nmi "
      "columns)")(
      "grid-step", po::value<std::string>()->default_value("2min"), "envelope time-grid step")(
      "grid-end", po::value<std::string>()->default_value("90min"), "envelope time-grid end");
  if (monte_carlo) {
    d.add_options()("samples", po::value<std::string>()->default_value("100000"), "Monte Carlo samples, in [2, 2^40]")(
        "seed", po::value<std::string>()->default_value("1"), "seed of the counter-based random streams")(
        "threads", po::value<int>()->default_value(0), "worker threads (0 = all cores, at most 1024); never changes results");
  }
  d.add(model_options_description());
  d.add(test_run_options_description());
  d.add(uncertainty_options_description());
  return d;
}

po::options_description test_run_options_description() {
  po::options_description d("Preflight test run, measurements and realignment (chapters 4, 5)");
  d.add_options()("test-duration", po::value<std::string>()->default_value("15min"),
                  "test-run length T on the stationary base, in (0, 2h] (a whole number of filter intervals, at least 4; a Monte Carlo study at most 1800)")(
      "filter-interval", po::value<std::string>()->default_value("10s"), "filter-box counting interval tau (fig. 5.2), >= 0.1s")(
      "dv-pulse", po::value<std::string>()->default_value("0.1ftps"),
      "accelerometer pulse weight (velocity increment), in [0, 1mps]; 0mps = continuous output")(
      "position-resolution", po::value<std::string>()->default_value("3ft"),
      "resolution of the position computer, in [0, 1km]; 0m = exact")(
      "fit-u4", po::value<std::string>()->default_value("auto"),
      "fit the U4 (t^2) term: auto (when resolvable by (4.6)), yes (error if not), no")(
      "sway", po::value<std::string>()->default_value("off"),
      "vehicle sway as VELOCITY_RMS,CORRELATION_TIME (e.g. 5mmps,6s: a parked aircraft in light wind; RMS in [0, 1mps], time in [0.1s, 1h]) or off")(
      "realignment-duration", po::value<std::string>()->default_value("10min"),
      "realignment time of 5.1.1, 5.1.2, combined (adds to ready_time_min), in [0, 6h]")(
      "alignment-average", po::value<std::string>()->default_value("10min"),
      "5.4: averaging time of the alignment-phase torquer commands and accelerometer outputs, in (0, 6h]")(
      "torquer-pulse", po::value<std::string>()->default_value("1arcsec"),
      "5.4: angle per gyro torquer pulse (resolution of the command measurement), in [0, 1mrad]; 0rad = exact")(
      "alignment-time", po::value<std::string>()->default_value("steady"),
      "truth level: fine-alignment time with the loops (2.9)/(2.13) simulated in the time domain, or steady "
      "(the loops' steady state)")(
      "coarse-misalignment", po::value<std::string>()->default_value("0.1mrad,0.1mrad,5mrad"),
      "with --alignment-time: misalignment C_x,C_y,C_z at the start of the fine alignment, each within ±0.1rad");
  return d;
}

TestRunOptions read_test_run_options(const po::variables_map& vm) {
  TestRunOptions t;
  // A comma list is a sweep (apps/sweep.h): the study itself starts from its first value.
  auto q = [&](const char* name, Dimension d) {
    return parse_quantity(split_commas(vm[name].as<std::string>()).front(), d, std::string("--") + name);
  };
  t.duration_s = q("test-duration", Dimension::kTime);
  t.filter_interval_s = q("filter-interval", Dimension::kTime);
  t.dv_pulse_mps = q("dv-pulse", Dimension::kVelocity);
  t.position_resolution_m = q("position-resolution", Dimension::kLength);
  t.realignment_duration_s = q("realignment-duration", Dimension::kTime);
  t.alignment_average_s = q("alignment-average", Dimension::kTime);
  t.torquer_pulse_rad = q("torquer-pulse", Dimension::kAngle);
  const std::string fit = vm["fit-u4"].as<std::string>();
  if (fit == "auto") t.fit_u4 = FitU4::kAuto;
  else if (fit == "yes") t.fit_u4 = FitU4::kYes;
  else if (fit == "no") t.fit_u4 = FitU4::kNo;
  else throw InputError("--fit-u4", fit, "must be auto, yes or no");
  const std::string sway = vm["sway"].as<std::string>();
  if (sway != "off") {
    const auto parts = split_commas(sway);
    if (parts.size() != 2) throw InputError("--sway", sway, "expected VELOCITY_RMS,CORRELATION_TIME (e.g. 5mmps,6s) or off");
    t.sway.velocity_rms_mps = parse_quantity(parts[0], Dimension::kVelocity, "--sway velocity");
    t.sway.correlation_time_s = parse_quantity(parts[1], Dimension::kTime, "--sway time");
  }
  // The coarse misalignment is read (and checked) even when the steady
  // alignment leaves it unused: a typo is refused, not ignored.
  AlignmentLoopSettings a;
  const std::string coarse = vm["coarse-misalignment"].as<std::string>();
  const auto parts = split_commas(coarse);
  if (parts.size() != 3)
    throw InputError("--coarse-misalignment", echo_input(coarse), "expected C_x,C_y,C_z (e.g. 1mrad,1mrad,5mrad)");
  for (int k = 0; k < 3; ++k)
    a.initial_misalignment_rad[k] =
        parse_quantity(parts[static_cast<std::size_t>(k)], Dimension::kAngle, "--coarse-misalignment");
  const std::string alignment = vm["alignment-time"].as<std::string>();
  if (alignment != "steady") {
    a.duration_s = parse_quantity(alignment, Dimension::kTime, "--alignment-time");
    a.average_s = t.alignment_average_s;
    validate(a);
    t.alignment_loops = a;
  } else {
    validate(a);  // the defaults of the rest, and the coarse misalignment given
  }
  validate(t);
  return t;
}

mc::StudyConfig read_study_config(const po::variables_map& vm, bool monte_carlo) {
  mc::StudyConfig c;
  c.systems.clear();
  for (const auto& s : split_commas(vm["system"].as<std::string>())) {
    const System sys = parse_system(s, "--system");
    for (System other : c.systems)
      if (other == sys) throw InputError("--system", vm["system"].as<std::string>(), "lists a system twice");
    c.systems.push_back(sys);
  }
  c.schemes.clear();
  const std::string schemes = vm["scheme"].as<std::string>();
  if (schemes == "all") {
    c.schemes = all_schemes();
  } else {
    for (const auto& s : split_commas(schemes)) c.schemes.push_back(parse_scheme(s));
  }
  c.fidelity = parse_fidelity(vm["fidelity"].as<std::string>(), "--fidelity");
  c.confidence = vm["confidence"].as<double>();
  c.grid_step_s = parse_quantity(vm["grid-step"].as<std::string>(), Dimension::kTime, "--grid-step");
  c.grid_end_s = parse_quantity(vm["grid-end"].as<std::string>(), Dimension::kTime, "--grid-end");
  bool uses_system2 = false;
  for (System s : c.systems) uses_system2 |= s == System::kGyrocompass;
  c.model = read_model_options(vm, uses_system2);
  c.uncertainties = read_uncertainty_model(vm);
  c.test = read_test_run_options(vm);
  if (monte_carlo) {
    c.samples = read_count(vm, "samples");
    c.seed = read_count(vm, "seed");
    c.threads = vm["threads"].as<int>();
  }
  mc::validate(c);
  return c;
}

mc::LengthUnit read_length_unit(const po::variables_map& vm) {
  const std::string u = vm["units"].as<std::string>();
  if (u == "si") return mc::LengthUnit::kMetre;
  if (u == "paper") return mc::LengthUnit::kFoot;
  if (u == "nmi") return mc::LengthUnit::kNauticalMile;
  throw InputError("--units", u, "must be si, paper or nmi");
}

}  // namespace insmc::app
