// insmc bench: throughput of each Monte Carlo path against the floor it is
// bound by, each pair measured in the same round (the machine is shared and
// noisy; only same-round ratios are meaningful):
//   paper, scheme none   the vectorised floor: generator + block map product + sums (throughput.h)
//   linear, scheme none  the same floor
//   paper, every scheme  the pipeline's batched products (pipeline_throughput.h)
//   linear, every scheme the same floor
//   truth, scheme none   a hand-written integrator of the same equations (truth_reference.h)
#include <algorithm>
#include <fmt/format.h>
#include <thread>
#include <vector>

#include "apps/cli_common.h"
#include "apps/progress.h"
#include "lib/common/input_error.h"
#include "lib/common/version.h"
#include "montecarlo/study/bench/pipeline_throughput.h"
#include "montecarlo/study/bench/throughput.h"
#include "montecarlo/study/bench/truth_throughput.h"
#include "montecarlo/report/json.h"

namespace insmc::app {
namespace {

struct Round {
  mc::ThroughputResult paper;
  mc::ThroughputResult linear;  ///< the same uncompensated study at the linear level
  mc::PipelineThroughput pipeline;
  mc::TruthThroughput truth;
  double engine_over_floor() const { return paper.engine_samples_per_s / paper.floor_samples_per_s; }
  double linear_engine_over_floor() const { return linear.engine_samples_per_s / linear.floor_samples_per_s; }
  double scaling() const { return paper.engine_samples_per_s / paper.engine_one_thread_samples_per_s; }
  double paper_full_over_floor() const { return pipeline.paper_samples_per_s / pipeline.floor_samples_per_s; }
  double linear_over_floor() const { return pipeline.linear_samples_per_s / pipeline.floor_samples_per_s; }
  double truth_over_reference() const { return truth.truth_samples_per_s / truth.reference_samples_per_s; }
};

double median(const std::vector<Round>& rounds, double (Round::*ratio)() const) {
  std::vector<double> v;
  for (const Round& r : rounds) v.push_back((r.*ratio)());
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

mc::Json round_json(const Round& r) {
  mc::Json x = mc::Json::object();
  x["generator_variates_per_s"] = r.paper.generator_variates_per_s;
  x["floor_samples_per_s"] = r.paper.floor_samples_per_s;
  x["engine_samples_per_s"] = r.paper.engine_samples_per_s;
  x["engine_over_floor"] = r.engine_over_floor();
  x["engine_one_thread_samples_per_s"] = r.paper.engine_one_thread_samples_per_s;
  x["linear_floor_samples_per_s"] = r.linear.floor_samples_per_s;
  x["linear_engine_samples_per_s"] = r.linear.engine_samples_per_s;
  x["linear_engine_over_floor"] = r.linear_engine_over_floor();
  x["pipeline_floor_samples_per_s"] = r.pipeline.floor_samples_per_s;
  x["paper_full_samples_per_s"] = r.pipeline.paper_samples_per_s;
  x["paper_full_over_floor"] = r.paper_full_over_floor();
  x["linear_samples_per_s"] = r.pipeline.linear_samples_per_s;
  x["linear_over_floor"] = r.linear_over_floor();
  x["truth_reference_samples_per_s"] = r.truth.reference_samples_per_s;
  x["truth_samples_per_s"] = r.truth.truth_samples_per_s;
  x["truth_over_reference"] = r.truth_over_reference();
  return x;
}

}  // namespace

int run_bench(const Args& args) {
  po::options_description opts("Options");
  opts.add_options()("samples", po::value<std::string>()->default_value("2000000"),
                     "samples per measurement of the uncompensated paper path, in [1024, 2^40] (whole blocks of 1024)")(
      "pipeline-samples", po::value<std::string>()->default_value("102400"),
      "samples per measurement of the full pipelines (paper, linear), in [1024, 2^40]")(
      "truth-samples", po::value<std::string>()->default_value("4096"), "samples per measurement of the truth path, in [1024, 2^40]")(
      "threads", po::value<int>()->default_value(0), "threads (0 = all cores)")(
      "rounds", po::value<int>()->default_value(3), "paired rounds, in [1, 50]; the median ratio is reported")(
      "json", po::bool_switch(), "print the JSON alone on stdout");
  const auto vm = parse_args(
      args, "bench", "[--samples N] [--pipeline-samples N] [--truth-samples N] [--threads N] [--rounds N] [--json]",
      opts);
  if (!vm) return 0;
  const std::uint64_t samples = read_count(*vm, "samples");
  const std::uint64_t pipeline_samples = read_count(*vm, "pipeline-samples");
  const std::uint64_t truth_samples = read_count(*vm, "truth-samples");
  const int rounds = (*vm)["rounds"].as<int>();
  int threads = (*vm)["threads"].as<int>();
  for (const auto& [name, n] : {std::pair{"--samples", samples}, std::pair{"--pipeline-samples", pipeline_samples},
                                std::pair{"--truth-samples", truth_samples}})
    if (n < mc::kBlockSize || n > mc::kMaxSamples)
      throw InputError(name, std::to_string(n), fmt::format("must lie in [1024, {}]", mc::kMaxSamples));
  if (rounds < 1 || rounds > 50) throw InputError("--rounds", std::to_string(rounds), "must lie in [1, 50]");
  if (threads < 0 || threads > mc::kMaxThreads)
    throw InputError("--threads", std::to_string(threads), fmt::format("must lie in [0, {}]", mc::kMaxThreads));
  if (threads == 0) threads = static_cast<int>(std::thread::hardware_concurrency());
  std::vector<Round> results;
  {
    // Three measurements a round (stderr, a terminal only).
    Progress progress(static_cast<std::uint64_t>(4 * rounds), "measurements");
    const auto measured = [&](int i, int k) { progress.update(static_cast<std::uint64_t>(4 * i + k)); };
    for (int i = 0; i < rounds; ++i) {
      Round r;
      r.paper = mc::measure_throughput(mc::benchmark_study(samples, threads));
      measured(i, 1);
      r.linear = mc::measure_throughput(mc::benchmark_study(samples, threads, Fidelity::kLinear));
      measured(i, 2);
      r.pipeline = mc::measure_pipeline_throughput(pipeline_samples, threads);
      measured(i, 3);
      r.truth = mc::measure_truth_throughput(mc::truth_study(truth_samples, threads));
      measured(i, 4);
      results.push_back(r);
    }
  }
  const double engine_median = median(results, &Round::engine_over_floor);
  const double linear_engine_median = median(results, &Round::linear_engine_over_floor);
  const mc::MachineDescription machine = mc::describe_machine();
  const double scaling_median = median(results, &Round::scaling);
  const double paper_full_median = median(results, &Round::paper_full_over_floor);
  const double linear_median = median(results, &Round::linear_over_floor);
  const double truth_median = median(results, &Round::truth_over_reference);
  const int outputs = results.back().paper.outputs;
  if ((*vm)["json"].as<bool>()) {
    mc::Json j = mc::Json::object();
    j["version"] = kVersion;
    j["study"] = "paper level, scheme none, systems 1 and 2, report times 42/63/84 min";
    j["samples"] = static_cast<double>(samples);
    j["pipeline_samples"] = static_cast<double>(pipeline_samples);
    j["truth_samples"] = static_cast<double>(truth_samples);
    j["threads"] = threads;
    j["outputs_per_sample"] = outputs;
    mc::Json m = mc::Json::object();
    m["cpu"] = machine.cpu;
    m["hardware_threads"] = machine.hardware_threads;
    m["generator_kernel"] = machine.generator_kernel;
    m["product_kernel"] = machine.product_kernel;
    j["machine"] = m;
    mc::Json floors = mc::Json::object();
    floors["paper_uncompensated"] =
        "vectorised: generator (draw-major, fastest kernel) + x-to-output block product (fastest kernel) + lane sums";
    floors["linear_uncompensated"] = "the same as paper_uncompensated (same shapes)";
    floors["paper_full"] = "generator + the pipeline's batched products (observation maps, fits, output map) + sums";
    floors["linear"] = "the same as paper_full (same shapes)";
    floors["truth"] = "hand-written fixed-step RK4 of the same equations, same steps";
    j["floors"] = floors;
    mc::Json rs = mc::Json::array();
    for (const Round& r : results) rs.push_back(round_json(r));
    j["rounds"] = rs;
    j["median_engine_over_floor"] = engine_median;
    j["median_linear_engine_over_floor"] = linear_engine_median;
    j["median_thread_scaling"] = scaling_median;
    j["median_paper_full_over_floor"] = paper_full_median;
    j["median_linear_over_floor"] = linear_median;
    j["median_truth_over_reference"] = truth_median;
    fmt::print("{}", j.dump());
    return 0;
  }
  fmt::print("insmc bench: {} threads; uncompensated {} samples ({} outputs), full pipelines {}, truth {}\n",
             threads, samples, outputs, pipeline_samples, truth_samples);
  fmt::print("machine: {}, {} hardware threads; generator kernel {}, block product kernel {}\n\n", machine.cpu,
             machine.hardware_threads, machine.generator_kernel, machine.product_kernel);
  fmt::print("| round | generator [variates/s, 1 thread] | floor [samples/s] | engine [samples/s] | engine/floor "
             "| engine, 1 thread [samples/s] | scaling |\n");
  fmt::print("|---:|---:|---:|---:|---:|---:|---:|\n");
  for (size_t i = 0; i < results.size(); ++i) {
    const Round& r = results[i];
    fmt::print("| {} | {:.3g} | {:.3g} | {:.3g} | {:.2f} | {:.3g} | {:.2f} |\n", i + 1,
               r.paper.generator_variates_per_s, r.paper.floor_samples_per_s, r.paper.engine_samples_per_s,
               r.engine_over_floor(), r.paper.engine_one_thread_samples_per_s, r.scaling());
  }
  fmt::print("\n| round | linear, scheme none: floor [samples/s] | engine [samples/s] | engine/floor |\n");
  fmt::print("|---:|---:|---:|---:|\n");
  for (size_t i = 0; i < results.size(); ++i) {
    const Round& r = results[i];
    fmt::print("| {} | {:.3g} | {:.3g} | {:.2f} |\n", i + 1, r.linear.floor_samples_per_s,
               r.linear.engine_samples_per_s, r.linear_engine_over_floor());
  }
  fmt::print("\n| round | pipeline floor [samples/s] | paper full [samples/s] | /floor | linear [samples/s] | /floor "
             "| truth reference [samples/s] | truth [samples/s] | /reference |\n");
  fmt::print("|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  for (size_t i = 0; i < results.size(); ++i) {
    const Round& r = results[i];
    fmt::print("| {} | {:.3g} | {:.3g} | {:.2f} | {:.3g} | {:.2f} | {:.3g} | {:.3g} | {:.2f} |\n", i + 1,
               r.pipeline.floor_samples_per_s, r.pipeline.paper_samples_per_s, r.paper_full_over_floor(),
               r.pipeline.linear_samples_per_s, r.linear_over_floor(), r.truth.reference_samples_per_s,
               r.truth.truth_samples_per_s, r.truth_over_reference());
  }
  fmt::print("\nmedians: paper uncompensated engine/floor {:.2f} ({}-thread/1-thread scaling {:.2f}); "
             "linear uncompensated {:.2f}; paper full/floor {:.2f}; linear/floor {:.2f}; truth/reference {:.2f} "
             "(time ratio {:.2f})\n",
             engine_median, threads, scaling_median, linear_engine_median, paper_full_median, linear_median,
             truth_median, 1.0 / truth_median);
  return 0;
}

}  // namespace insmc::app
