// insmc bench: throughput of the Monte Carlo engine against the machine's
// floor (generator + map + sums with no framework), measured in one run.
#include <algorithm>
#include <thread>
#include <fmt/format.h>
#include <vector>

#include "apps/cli_common.h"
#include "lib/common/input_error.h"
#include "lib/common/version.h"
#include "montecarlo/bench/throughput.h"
#include "montecarlo/write/json.h"

namespace insmc::app {

int run_bench(const Args& args) {
  po::options_description opts("Options");
  opts.add_options()("samples", po::value<std::uint64_t>()->default_value(2000000), "samples per measurement")(
      "threads", po::value<int>()->default_value(0), "threads (0 = all cores)")(
      "rounds", po::value<int>()->default_value(3), "paired rounds; the median ratio is reported")(
      "json", po::bool_switch(), "print the JSON alone on stdout");
  const auto vm = parse_args(args, "bench", "[--samples N] [--threads N] [--rounds N] [--json]", opts);
  if (!vm) return 0;
  const std::uint64_t samples = (*vm)["samples"].as<std::uint64_t>();
  const int rounds = (*vm)["rounds"].as<int>();
  int threads = (*vm)["threads"].as<int>();
  if (samples < mc::kBlockSize) throw InputError("--samples", std::to_string(samples), "must be >= 1024");
  if (rounds < 1 || rounds > 50) throw InputError("--rounds", std::to_string(rounds), "must lie in [1, 50]");
  if (threads < 0) throw InputError("--threads", std::to_string(threads), "must be >= 0");
  if (threads == 0) threads = static_cast<int>(std::thread::hardware_concurrency());
  std::vector<mc::ThroughputResult> results;
  std::vector<double> ratios, scaling;
  for (int i = 0; i < rounds; ++i) {
    results.push_back(mc::measure_throughput(mc::benchmark_study(samples, threads)));
    ratios.push_back(results.back().engine_samples_per_s / results.back().floor_samples_per_s);
    scaling.push_back(results.back().engine_samples_per_s / results.back().engine_one_thread_samples_per_s);
  }
  std::vector<double> sorted = ratios;
  std::sort(sorted.begin(), sorted.end());
  const double median = sorted[sorted.size() / 2];
  std::vector<double> sorted_scaling = scaling;
  std::sort(sorted_scaling.begin(), sorted_scaling.end());
  const double median_scaling = sorted_scaling[sorted_scaling.size() / 2];
  const mc::ThroughputResult& last = results.back();
  mc::Json j = mc::Json::object();
  j["version"] = kVersion;
  j["study"] = "paper level, scheme none, systems 1 and 2, report times 42/63/84 min";
  j["samples"] = static_cast<double>(samples);
  j["threads"] = threads;
  j["outputs_per_sample"] = last.outputs;
  mc::Json rs = mc::Json::array();
  for (const auto& r : results) {
    mc::Json x = mc::Json::object();
    x["generator_variates_per_s"] = r.generator_variates_per_s;
    x["floor_samples_per_s"] = r.floor_samples_per_s;
    x["engine_samples_per_s"] = r.engine_samples_per_s;
    x["engine_over_floor"] = r.engine_samples_per_s / r.floor_samples_per_s;
    x["engine_one_thread_samples_per_s"] = r.engine_one_thread_samples_per_s;
    rs.push_back(x);
  }
  j["rounds"] = rs;
  j["median_engine_over_floor"] = median;
  j["median_thread_scaling"] = median_scaling;
  if ((*vm)["json"].as<bool>()) {
    fmt::print("{}", j.dump());
    return 0;
  }
  fmt::print("insmc bench: {} samples, {} threads, {} outputs per sample (paper level, report times)\n\n",
             samples, threads, last.outputs);
  fmt::print("| round | generator [variates/s, 1 thread] | floor [samples/s] | engine [samples/s] | engine/floor "
             "| engine, 1 thread [samples/s] | scaling |\n");
  fmt::print("|---:|---:|---:|---:|---:|---:|---:|\n");
  for (size_t i = 0; i < results.size(); ++i)
    fmt::print("| {} | {:.3g} | {:.3g} | {:.3g} | {:.2f} | {:.3g} | {:.2f} |\n", i + 1,
               results[i].generator_variates_per_s, results[i].floor_samples_per_s, results[i].engine_samples_per_s,
               ratios[i], results[i].engine_one_thread_samples_per_s, scaling[i]);
  fmt::print("\nmedian engine/floor: {:.2f}; median {}-thread/1-thread scaling: {:.2f}\n", median, threads,
             median_scaling);
  return 0;
}

}  // namespace insmc::app
