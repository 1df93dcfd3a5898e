#pragma once
/// `insmc bench`: rounds of paired measurements of each Monte Carlo path
/// against the floor it is bound by, each pair in the same round (the
/// machine is shared and noisy; only same-round ratios are meaningful):
///   paper, scheme none   the vectorised floor: generator + block map product + sums (throughput.h)
///   linear, scheme none  the same floor
///   paper, every scheme  the pipeline's batched products (pipeline_throughput.h)
///   linear, every scheme the same floor
///   truth, scheme none   a hand-written integrator of the same equations (truth_reference.h)
/// and their report: the rounds and the median ratios (markdown, json).
#include <cstdint>
#include <functional>
#include <vector>

#include "montecarlo/report/report.h"
#include "montecarlo/study/bench/pipeline_throughput.h"
#include "montecarlo/study/bench/throughput.h"
#include "montecarlo/study/bench/truth_throughput.h"

namespace insmc::mc {

struct BenchOptions {
  std::uint64_t samples = 2000000;         ///< per measurement of the uncompensated paths
  std::uint64_t pipeline_samples = 102400;  ///< per measurement of the full pipelines
  std::uint64_t truth_samples = 4096;       ///< per measurement of the truth path
  int threads = 1;
  int rounds = 3;
  /// After each measurement: (round, measurement 1..4).
  std::function<void(int, int)> measured;
};

/// One round's four measurements.
struct BenchRound {
  ThroughputResult paper;
  ThroughputResult linear;  ///< the same uncompensated study at the linear level
  PipelineThroughput pipeline;
  TruthThroughput truth;
  double engine_over_floor() const { return paper.engine_samples_per_s / paper.floor_samples_per_s; }
  double linear_engine_over_floor() const { return linear.engine_samples_per_s / linear.floor_samples_per_s; }
  double scaling() const { return paper.engine_samples_per_s / paper.engine_one_thread_samples_per_s; }
  double paper_full_over_floor() const { return pipeline.paper_samples_per_s / pipeline.floor_samples_per_s; }
  double linear_over_floor() const { return pipeline.linear_samples_per_s / pipeline.floor_samples_per_s; }
  double truth_over_reference() const { return truth.truth_samples_per_s / truth.reference_samples_per_s; }
};

std::vector<BenchRound> run_bench_rounds(const BenchOptions& options);

ReportOutline bench_report_outline();
Report bench_report(const BenchOptions& options, const std::vector<BenchRound>& rounds);

}  // namespace insmc::mc
