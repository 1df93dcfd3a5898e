// insmc bench: throughput of each Monte Carlo path against the floor it is
// bound by, each pair measured in the same round
// (montecarlo/study/bench/bench_report.h).
#include <fmt/format.h>
#include <thread>
#include <vector>

#include "apps/cli_common.h"
#include "apps/progress.h"
#include "apps/report_output.h"
#include "lib/common/input_error.h"
#include "montecarlo/study/bench/bench_report.h"

namespace insmc::app {

int cmd_bench(const Args& args) {
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
  mc::BenchOptions options;
  options.samples = samples;
  options.pipeline_samples = pipeline_samples;
  options.truth_samples = truth_samples;
  options.threads = threads;
  options.rounds = rounds;
  std::vector<mc::BenchRound> results;
  {
    // Four measurements a round (stderr, a terminal only).
    Progress progress(static_cast<std::uint64_t>(4 * rounds), "measurements");
    options.measured = [&](int i, int k) { progress.update(static_cast<std::uint64_t>(4 * i + k)); };
    results = mc::run_bench_rounds(options);
    options.measured = nullptr;  // it refers to `progress`, which ends here
  }
  const StdoutChoice shown{(*vm)["json"].as<bool>() ? mc::ReportFormat::kJson : mc::ReportFormat::kMarkdown};
  std::optional<OutputFolderOption> no_set;
  write_report(mc::bench_report(options, results), shown, no_set, *vm);
  return 0;
}

}  // namespace insmc::app
