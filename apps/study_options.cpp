#include "apps/study_options.h"

namespace insmc::app {

po::options_description uncertainty_options_description() {
  po::options_description d("Uncertainties (names: insmc params)");
  d.add_options()("bound", po::value<std::vector<std::string>>()->composing(),
                  "NAME=VALUE with unit, e.g. gyro_drift=3meru, accel_bias_x=0.5mg; NAME is a "
                  "catalogue name, a group or all; repeatable")(
      "dist", po::value<std::vector<std::string>>()->composing(),
      "NAME=uniform|normal:K|fixed:VALUE|zero (bound = K sigma for normal); repeatable, applied "
      "in order, e.g. --dist all=zero --dist gyro_drift_z=fixed:10meru");
  return d;
}

UncertaintyModel read_uncertainty_model(const po::variables_map& vm) {
  UncertaintyModel model;
  if (vm.count("bound"))
    for (const auto& a : vm["bound"].as<std::vector<std::string>>()) model.apply_bound(a);
  if (vm.count("dist"))
    for (const auto& a : vm["dist"].as<std::vector<std::string>>()) model.apply_dist(a);
  return model;
}

}  // namespace insmc::app

#include <charconv>
#include <fmt/format.h>

#include "lib/common/input_error.h"
#include "lib/units/quantity.h"

namespace insmc::app {
namespace {

std::uint64_t parse_count(const std::string& text, const std::string& field) {
  std::uint64_t v = 0;
  const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (ec != std::errc() || ptr != text.data() + text.size())
    throw InputError(field, text, "must be a non-negative integer");
  return v;
}

}  // namespace

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
      "paper (the report's closed forms as printed) or linear (full linear model, report errors corrected)")(
      "confidence", po::value<double>()->default_value(0.95), "confidence level of the RMS intervals, in (0, 1)")(
      "units", po::value<std::string>()->default_value("si"), "si (metres, _m columns) or paper (feet, _ft columns)")(
      "grid-step", po::value<std::string>()->default_value("2min"), "envelope time-grid step")(
      "grid-end", po::value<std::string>()->default_value("90min"), "envelope time-grid end");
  if (monte_carlo) {
    d.add_options()("samples", po::value<std::string>()->default_value("100000"), "Monte Carlo samples, >= 2")(
        "seed", po::value<std::string>()->default_value("1"), "seed of the counter-based random streams")(
        "threads", po::value<int>()->default_value(0), "worker threads (0 = all cores); never changes results");
  }
  d.add(model_options_description());
  d.add(uncertainty_options_description());
  return d;
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
  if (monte_carlo) {
    c.samples = parse_count(vm["samples"].as<std::string>(), "--samples");
    c.seed = parse_count(vm["seed"].as<std::string>(), "--seed");
    c.threads = vm["threads"].as<int>();
  }
  mc::validate(c);
  return c;
}

mc::LengthUnit read_length_unit(const po::variables_map& vm) {
  const std::string u = vm["units"].as<std::string>();
  if (u == "si") return mc::LengthUnit::kMetre;
  if (u == "paper") return mc::LengthUnit::kFoot;
  throw InputError("--units", u, "must be si or paper");
}

}  // namespace insmc::app
