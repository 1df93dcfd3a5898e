#include "apps/sweep.h"

#include <algorithm>
#include <cctype>
#include <fmt/format.h>

#include "apps/study_options.h"
#include "lib/common/input_error.h"
#include "lib/common/input_text.h"
#include "lib/uncertainty/random_fraction.h"
#include "lib/units/quantity.h"
#include "lib/units/units.h"

namespace insmc::app {
namespace {

struct QuantityOption {
  const char* option;
  const char* column;
  Dimension dimension;
  double TestRunOptions::*field;  // null: latitude
};

constexpr QuantityOption kSweepable[] = {
    {"test-duration", "test_duration_s", Dimension::kTime, &TestRunOptions::duration_s},
    {"filter-interval", "filter_interval_s", Dimension::kTime, &TestRunOptions::filter_interval_s},
    {"dv-pulse", "dv_pulse_mps", Dimension::kVelocity, &TestRunOptions::dv_pulse_mps},
    {"position-resolution", "position_resolution_m", Dimension::kLength, &TestRunOptions::position_resolution_m},
    {"realignment-duration", "realignment_duration_s", Dimension::kTime, &TestRunOptions::realignment_duration_s},
    {"alignment-average", "alignment_average_s", Dimension::kTime, &TestRunOptions::alignment_average_s},
    {"torquer-pulse", "torquer_pulse_rad", Dimension::kAngle, &TestRunOptions::torquer_pulse_rad},
    {"latitude", "latitude_rad", Dimension::kAngle, nullptr},
};

SweepAxis axis_of(const std::string& column, const std::string& option, const std::vector<std::string>& texts,
                  Dimension d) {
  SweepAxis a;
  a.column = column;
  a.texts = texts;
  for (const auto& t : texts) a.values_si.push_back(parse_quantity(t, d, fmt::format("--{}", option)));
  return a;
}

}  // namespace

void refuse_sweeps(const po::variables_map& vm, const std::string& subcommand) {
  std::vector<std::string> names = {"bound", "random-fraction"};
  for (const QuantityOption& q : kSweepable) names.emplace_back(q.option);
  for (const std::string& name : names) {
    if (!vm.count(name) || vm[name].defaulted()) continue;
    const boost::any& v = vm[name].value();
    std::vector<std::string> values;
    if (const auto* one = boost::any_cast<std::string>(&v)) values.push_back(*one);
    if (const auto* many = boost::any_cast<std::vector<std::string>>(&v)) values = *many;
    for (const std::string& value : values)
      if (value.find(',') != std::string::npos)
        throw InputError("--" + name, echo_input(value),
                         fmt::format("a comma list is a sweep, which insmc run takes; insmc {} takes one value",
                                     subcommand));
  }
}

std::vector<SweepAxis> find_sweeps(const po::variables_map& vm) {
  std::vector<SweepAxis> axes;
  for (const QuantityOption& q : kSweepable) {
    if (!vm.count(q.option)) continue;
    const std::vector<std::string> texts = split_commas(vm[q.option].as<std::string>());
    if (texts.size() < 2) continue;
    SweepAxis a = axis_of(q.column, q.option, texts, q.dimension);
    const auto values = a.values_si;
    const auto field = q.field;
    a.apply = [values, field](mc::StudyConfig& c, std::size_t i) {
      if (field) c.test.*field = values[i];
      else c.model.latitude_rad = values[i];
      // The loops average over --alignment-average as the single value does
      // (apps/study_options.cpp), and their own check sees each point's.
      if (field == &TestRunOptions::alignment_average_s && c.test.alignment_loops)
        c.test.alignment_loops->average_s = values[i];
    };
    axes.push_back(std::move(a));
  }
  if (vm.count("bound")) {
    for (const auto& assignment : vm["bound"].as<std::vector<std::string>>()) {
      const auto [indices, list] = split_assignment(assignment, "--bound");
      const std::vector<std::string> texts = split_commas(list);
      if (texts.size() < 2) continue;
      const std::string name = assignment.substr(0, assignment.find('='));
      const UncertaintySpec& spec = catalogue()[indices.front()];
      SweepAxis a = axis_of(fmt::format("{}.bound_{}", name, si_suffix(spec.dimension)), fmt::format("bound {}", name), texts,
                            spec.dimension);
      a.apply = [name, texts](mc::StudyConfig& c, std::size_t i) { c.uncertainties.apply_bound(fmt::format("{}={}", name, texts[i])); };
      axes.push_back(std::move(a));
    }
  }
  if (vm.count("random-fraction")) {
    const std::vector<std::string> texts = split_commas(vm["random-fraction"].as<std::string>());
    if (texts.size() >= 2) {
      SweepAxis a = axis_of("random_fraction", "random-fraction", texts, Dimension::kDimensionless);
      for (const std::string& t : texts) parse_random_fraction(t);  // each in [0, 1] before any point runs
      // --bound on the split's names wins over the fraction, as without a sweep
      // (this axis is applied before the --bound axes: point_config goes last to first).
      std::vector<std::string> bounds;
      if (vm.count("bound")) bounds = vm["bound"].as<std::vector<std::string>>();
      a.apply = [values = a.values_si, bounds](mc::StudyConfig& c, std::size_t i) {
        apply_random_fraction(c.uncertainties, values[i]);
        for (const std::string& b : bounds) c.uncertainties.apply_bound(b);
      };
      axes.push_back(std::move(a));
    }
  }
  check_sweep_size(axes);
  return axes;
}

}  // namespace insmc::app
