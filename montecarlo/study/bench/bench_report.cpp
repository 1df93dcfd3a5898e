#include "montecarlo/study/bench/bench_report.h"

#include <algorithm>
#include <fmt/format.h>

#include "lib/common/version.h"
#include "montecarlo/report/json.h"
#include "montecarlo/report/markdown.h"

namespace insmc::mc {
namespace {

double median(const std::vector<BenchRound>& rounds, double (BenchRound::*ratio)() const) {
  std::vector<double> v;
  for (const BenchRound& r : rounds) v.push_back((r.*ratio)());
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

Json round_json(const BenchRound& r) {
  Json x = Json::object();
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

std::vector<BenchRound> run_bench_rounds(const BenchOptions& o) {
  std::vector<BenchRound> results;
  for (int i = 0; i < o.rounds; ++i) {
    BenchRound r;
    const auto measured = [&](int k) {
      if (o.measured) o.measured(i, k);
    };
    r.paper = measure_throughput(benchmark_study(o.samples, o.threads));
    measured(1);
    r.linear = measure_throughput(benchmark_study(o.samples, o.threads, Fidelity::kLinear));
    measured(2);
    r.pipeline = measure_pipeline_throughput(o.pipeline_samples, o.threads);
    measured(3);
    r.truth = measure_truth_throughput(truth_study(o.truth_samples, o.threads));
    measured(4);
    results.push_back(r);
  }
  return results;
}

ReportOutline bench_report_outline() { return {"bench", {}, {}, {ReportFormat::kMarkdown, ReportFormat::kJson}}; }

Report bench_report(const BenchOptions& o, const std::vector<BenchRound>& results) {
  const double engine_median = median(results, &BenchRound::engine_over_floor);
  const double linear_engine_median = median(results, &BenchRound::linear_engine_over_floor);
  const MachineDescription machine = describe_machine();
  const double scaling_median = median(results, &BenchRound::scaling);
  const double paper_full_median = median(results, &BenchRound::paper_full_over_floor);
  const double linear_median = median(results, &BenchRound::linear_over_floor);
  const double truth_median = median(results, &BenchRound::truth_over_reference);
  const int outputs = results.back().paper.outputs;
  Json j = Json::object();
  j["version"] = kVersion;
  j["study"] = "paper level, scheme none, systems 1 and 2, report times 42/63/84 min";
  j["samples"] = static_cast<double>(o.samples);
  j["pipeline_samples"] = static_cast<double>(o.pipeline_samples);
  j["truth_samples"] = static_cast<double>(o.truth_samples);
  j["threads"] = o.threads;
  j["outputs_per_sample"] = outputs;
  Json m = Json::object();
  m["cpu"] = machine.cpu;
  m["hardware_threads"] = machine.hardware_threads;
  m["generator_kernel"] = machine.generator_kernel;
  m["product_kernel"] = machine.product_kernel;
  j["machine"] = m;
  Json floors = Json::object();
  floors["paper_uncompensated"] =
      "vectorised: generator (draw-major, fastest kernel) + x-to-output block product (fastest kernel) + lane sums";
  floors["linear_uncompensated"] = "the same as paper_uncompensated (same shapes)";
  floors["paper_full"] = "generator + the pipeline's batched products (observation maps, fits, output map) + sums";
  floors["linear"] = "the same as paper_full (same shapes)";
  floors["truth"] = "hand-written fixed-step RK4 of the same equations, same steps";
  j["floors"] = floors;
  Json rs = Json::array();
  for (const BenchRound& r : results) rs.push_back(round_json(r));
  j["rounds"] = rs;
  j["median_engine_over_floor"] = engine_median;
  j["median_linear_engine_over_floor"] = linear_engine_median;
  j["median_thread_scaling"] = scaling_median;
  j["median_paper_full_over_floor"] = paper_full_median;
  j["median_linear_over_floor"] = linear_median;
  j["median_truth_over_reference"] = truth_median;
  std::string md;
  md += fmt::format("insmc bench: {} threads; uncompensated {} samples ({} outputs), full pipelines {}, truth {}\n",
                    o.threads, o.samples, outputs, o.pipeline_samples, o.truth_samples);
  md += fmt::format("machine: {}, {} hardware threads; generator kernel {}, block product kernel {}\n\n", machine.cpu,
                    machine.hardware_threads, machine.generator_kernel, machine.product_kernel);
  Table paper({"round", "generator [variates/s, 1 thread]", "floor [samples/s]", "engine [samples/s]", "engine/floor",
               "engine, 1 thread [samples/s]", "scaling"});
  Table linear({"round", "linear, scheme none: floor [samples/s]", "engine [samples/s]", "engine/floor"});
  Table pipelines({"round", "pipeline floor [samples/s]", "paper full [samples/s]", "/floor", "linear [samples/s]",
                   "/floor", "truth reference [samples/s]", "truth [samples/s]", "/reference"});
  const auto rate = [](double x) { return fmt::format("{:.3g}", x); };
  const auto ratio = [](double x) { return fmt::format("{:.2f}", x); };
  for (size_t i = 0; i < results.size(); ++i) {
    const BenchRound& r = results[i];
    const std::string round = std::to_string(i + 1);
    paper.add_row({round, rate(r.paper.generator_variates_per_s), rate(r.paper.floor_samples_per_s),
                   rate(r.paper.engine_samples_per_s), ratio(r.engine_over_floor()),
                   rate(r.paper.engine_one_thread_samples_per_s), ratio(r.scaling())});
    linear.add_row({round, rate(r.linear.floor_samples_per_s), rate(r.linear.engine_samples_per_s),
                    ratio(r.linear_engine_over_floor())});
    pipelines.add_row({round, rate(r.pipeline.floor_samples_per_s), rate(r.pipeline.paper_samples_per_s),
                       ratio(r.paper_full_over_floor()), rate(r.pipeline.linear_samples_per_s),
                       ratio(r.linear_over_floor()), rate(r.truth.reference_samples_per_s),
                       rate(r.truth.truth_samples_per_s), ratio(r.truth_over_reference())});
  }
  md += render_markdown(paper) + "\n" + render_markdown(linear) + "\n" + render_markdown(pipelines);
  md += fmt::format("\nmedians: paper uncompensated engine/floor {:.2f} ({}-thread/1-thread scaling {:.2f}); "
                    "linear uncompensated {:.2f}; paper full/floor {:.2f}; linear/floor {:.2f}; truth/reference {:.2f} "
                    "(time ratio {:.2f})\n",
                    engine_median, o.threads, scaling_median, linear_engine_median, paper_full_median, linear_median,
                    truth_median, 1.0 / truth_median);
  Report report(bench_report_outline());
  report.shown(ReportFormat::kJson, j.dump()).shown(ReportFormat::kMarkdown, std::move(md));
  return report;
}

}  // namespace insmc::mc
