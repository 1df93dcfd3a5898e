// insmc run: the Monte Carlo study. Prints the envelope table, writes the
// output files of the README's contract into --out DIR.
#include <chrono>
#include <fmt/format.h>

#include "apps/cli_common.h"
#include "apps/progress.h"
#include "apps/study_options.h"
#include "lib/common/input_error.h"
#include "lib/uncertainty/catalogue.h"
#include "montecarlo/engine/engine.h"
#include "montecarlo/sampler/sampler.h"
#include "montecarlo/write/csv.h"

namespace insmc::app {
namespace {

/// --replay: one sample alone, its uncertainties and its outputs at the report times.
int replay(const mc::StudyConfig& c, const mc::StudyLayout& l, const mc::StudyMap& map, std::uint64_t index) {
  const UncertaintyVector x = mc::Sampler(c.uncertainties).draw(c.seed, index);
  fmt::print("# sample {} (seed {})\n\nuncertainty,value_si\n", index, c.seed);
  for (const auto& spec : catalogue()) fmt::print("{},{}\n", spec.name, mc::format_number(x[spec.index]));
  const std::vector<double> out = mc::evaluate_sample(c, map, l, x);
  fmt::print("\nscheme,system,axis,t_min,error_m\n");
  for (size_t o = 0; o < l.outputs.size(); ++o) {
    const auto& s = l.outputs[o];
    if (!l.is_report_time[s.time_index]) continue;
    fmt::print("{},{},{},{},{}\n", to_string(s.scheme), system_number(s.system), to_string(s.axis),
               mc::format_number(l.times_s[s.time_index] / 60), mc::format_number(out[o]));
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

  const mc::EnvelopeFiles files = mc::render_envelope(config, layout, acc, unit);
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
