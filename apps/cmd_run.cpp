// insmc run: the Monte Carlo study. Prints the envelope table, writes the
// output files of the README's contract into --out DIR.
#include <chrono>
#include <fmt/format.h>

#include "apps/cli_common.h"
#include "apps/progress.h"
#include "apps/study_options.h"
#include "apps/sweep.h"
#include "lib/common/input_error.h"
#include "lib/uncertainty/catalogue.h"
#include "montecarlo/engine/engine.h"
#include "lib/compensation/extended_vector.h"
#include "montecarlo/sampler/sampler.h"
#include "montecarlo/write/csv.h"

namespace insmc::app {
namespace {

/// --replay: one sample alone: its uncertainties, what its test run and
/// alignment produced (the extended vector z per system) and its errors.
int replay(const mc::StudyConfig& c, const mc::StudyLayout& l, const mc::StudyMap& map, std::uint64_t index) {
  const UncertaintyVector x = mc::Sampler(c.uncertainties).draw(c.seed, index);
  fmt::print("# sample {} (seed {}, fidelity {})\n\nuncertainty,value_si\n", index, c.seed, to_string(c.fidelity));
  for (const auto& spec : catalogue()) fmt::print("{},{}\n", spec.name, mc::format_number(x[spec.index]));
  static const char* const kSlots[][2] = {
      {"realignment zeta_r", "rad"}, {"realignment bias change", "mps2"}, {"realignment velocity", "mps"},
      {"U2 hat (position fit)", ""}, {"U3 hat (position fit)", ""},      {"U3 hat (accelerometer fit)", ""},
      {"filtered delta f(T)", "mps2"}, {"alignment torquer commands", "radps"},
      {"alignment accelerometer outputs", "mps2"}, {"velocity wiggle at T", "mps"}};
  const int starts[] = {ez::kRealignZeta, ez::kRealignBias, ez::kRealignVelocity, ez::kU2, ez::kU3, ez::kU3Accel,
                        ez::kDfT, ez::kTorquerCommands, ez::kAlignAccel, ez::kWiggleAtT, ez::kDim};
  Eigen::MatrixXd xm = x, z(ez::kDim, 1);
  for (std::size_t j = 0; j < c.systems.size(); ++j) {
    map.pipeline(static_cast<int>(j)).extended_vectors(index, 1, xm, z);
    fmt::print("\nsystem {}: estimates and measurements (fitted {})\nquantity,x,y,z\n", system_number(c.systems[j]),
               map.fitted_terms(static_cast<int>(j)));
    for (int q = 0; q < 10; ++q) {
      std::string row = fmt::format("{}{}", kSlots[q][0], *kSlots[q][1] ? fmt::format(" [{}]", kSlots[q][1]) : "");
      for (int i = starts[q]; i < starts[q + 1]; ++i) row += fmt::format(",{}", mc::format_number(z(i, 0)));
      fmt::print("{}\n", row);
    }
  }
  const std::vector<double> out = mc::evaluate_sample(c, map, l, index, x);
  fmt::print("\nscheme,system,clock,axis,t_min,error_m\n");
  for (size_t o = 0; o < l.outputs.size(); ++o) {
    const auto& s = l.outputs[o];
    if (!l.is_report_time[s.time_index]) continue;
    fmt::print("{},{},{},{},{},{}\n", to_string(s.scheme), system_number(s.system), clock_of(s.scheme),
               to_string(s.axis), mc::format_number(l.times_s[s.time_index] / 60), mc::format_number(out[o]));
  }
  return 0;
}

}  // namespace

int run_run(const Args& args) {
  po::options_description opts("Options");
  opts.add_options()("out", po::value<std::string>(), "folder for envelope.csv, envelope_grid.csv, envelope.md, "
                                                      "envelope.svg and run.json (created if needed)")(
      "format", po::value<std::string>()->default_value("markdown"),
      "stdout: markdown (readable table), csv (envelope.csv alone) or json (run.json alone)")(
      "replay", po::value<std::string>(), "recompute sample INDEX alone and print its uncertainties and errors");
  opts.add(study_options_description(true));
  const auto vm = parse_args(args, "run", "[options]", opts);
  if (!vm) return 0;
  const mc::StudyConfig config = read_study_config(*vm, true);
  const OutputFormat format = parse_output_format((*vm)["format"].as<std::string>());
  const mc::LengthUnit unit = read_length_unit(*vm);
  const std::vector<SweepAxis> sweeps = find_sweeps(*vm);
  if (!sweeps.empty()) {
    if (vm->count("replay")) throw InputError("--replay", (*vm)["replay"].as<std::string>(), "cannot be combined with a sweep");
    const SweepFiles files = run_sweep(config, sweeps, unit == mc::LengthUnit::kFoot);
    if (vm->count("out"))
      write_output_files((*vm)["out"].as<std::string>(), {{"sweep.csv", files.sweep_csv}, {"sweep.md", files.summary_md},
                                                          {"sweep.svg", files.plot_svg}});
    fmt::print("{}", format == OutputFormat::kCsv ? files.sweep_csv : files.summary_md);
    return 0;
  }
  const mc::StudyLayout layout = mc::make_layout(config);
  const mc::StudyMap map(config, layout);

  if (vm->count("replay")) {
    const std::string text = (*vm)["replay"].as<std::string>();
    std::uint64_t index = 0;
    try {
      std::size_t used = 0;
      index = std::stoull(text, &used);
      if (used != text.size()) throw std::invalid_argument(text);
    } catch (const std::exception&) {
      throw InputError("--replay", text, "must be a sample index, 0 <= INDEX < --samples");
    }
    if (index >= config.samples)
      throw InputError("--replay", text, fmt::format("must be below --samples = {}", config.samples));
    return replay(config, layout, map, index);
  }

  const auto start = std::chrono::steady_clock::now();
  Progress progress(config.samples);
  const mc::StudyAccumulator acc = mc::run_blocks(config, map, 0, mc::block_count(config.samples),
                                                  [&](std::uint64_t done) { progress.update(done); });
  const double elapsed_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  const mc::EnvelopeFiles files = mc::render_envelope(config, layout, map, acc, unit);
  mc::Json run = mc::Json::object();
  run["settings"] = mc::settings_json(config);
  run["elapsed_s"] = elapsed_s;
  run["resumed_from_sample"] = 0;
  run["envelope"] = files.envelope_json;
  const std::string run_json = run.dump();

  if (vm->count("out")) {
    write_output_files((*vm)["out"].as<std::string>(), {{"envelope.csv", files.envelope_csv},
                                                        {"envelope_grid.csv", files.envelope_grid_csv},
                                                        {"envelope.md", files.envelope_md},
                                                        {"envelope.svg", files.envelope_svg},
                                                        {"run.json", run_json}});
  }
  switch (format) {
    case OutputFormat::kCsv: fmt::print("{}", files.envelope_csv); break;
    case OutputFormat::kJson: fmt::print("{}", run_json); break;
    case OutputFormat::kMarkdown:
      fmt::print("insmc run: {} samples, seed {}, fidelity {}, {:.2f} s\n\n{}", config.samples, config.seed,
                 to_string(config.fidelity), elapsed_s, files.summary_text);
      break;
  }
  return 0;
}

}  // namespace insmc::app
