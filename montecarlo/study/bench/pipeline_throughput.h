#pragma once
/// The full-pipeline paths of `insmc bench`: `insmc run --fidelity paper`
/// and `--fidelity linear` with every scheme (the preflight test run, its
/// simulated pulse counts and position readings, the least-squares fits, the
/// alignment-phase measurements), against one floor measured in the same
/// call.
///
/// The floor: what the pipeline cannot avoid once it simulates the
/// quantizers on each sample's observations — the generator for every
/// variate it uses, the batched sensitivity products at the machine's GEMM
/// rate (the 3K × 33 velocity and position observation maps, the
/// estimators on the K data of each axis, the output map on z) and the
/// output sums, with no quantization, no per-sample layout and no
/// aggregator. Both levels have the same shapes, so one floor serves both.
/// (Without the quantizers the whole chain is linear in x and would fold
/// into the uncompensated floor of throughput.h; the quantizers are why the
/// observations must exist sample by sample.)
#include <cstdint>

#include "montecarlo/study/model/study_config.h"

namespace insmc::mc {

struct PipelineThroughput {
  double floor_samples_per_s;   ///< batched products, `threads` threads
  double paper_samples_per_s;   ///< run_blocks, paper level, every scheme
  double linear_samples_per_s;  ///< run_blocks, linear level, every scheme
};

PipelineThroughput measure_pipeline_throughput(std::uint64_t samples, int threads);

}  // namespace insmc::mc
