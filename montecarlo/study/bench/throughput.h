#pragma once
/// Throughput measurements shared by `insmc bench` and the Google Benchmark
/// target: the generator alone, the floor (generator + map + sums with no
/// framework around it) and the engine on the real study, measured in the
/// same run so that their ratio is meaningful on a noisy machine.
#include <cstdint>
#include <string>

#include "montecarlo/study/model/study_config.h"

namespace insmc::mc {

struct ThroughputResult {
  double generator_variates_per_s;  ///< uniform variates per second, one thread
  double floor_samples_per_s;       ///< hand-written loop, `threads` threads
  double engine_samples_per_s;      ///< run_blocks on the study, `threads` threads
  double engine_one_thread_samples_per_s;  ///< the same on one thread (for the scaling ratio)
  std::uint64_t samples;
  int threads;
  int outputs;                      ///< outputs per sample of the study
};

/// The uncompensated paper-level study at the report times (no grid),
/// systems 1 and 2: 33 uncertainties → 30 map rows → 24 outputs.
/// What the numbers were measured on: the CPU's model name
/// (/proc/cpuinfo, "unknown" elsewhere), its hardware threads, and the
/// kernels the generator and the block product chose at run time.
struct MachineDescription {
  std::string cpu;
  int hardware_threads;
  std::string generator_kernel;
  std::string product_kernel;
};
MachineDescription describe_machine();

StudyConfig benchmark_study(std::uint64_t samples, int threads, Fidelity fidelity = Fidelity::kPaper);

ThroughputResult measure_throughput(const StudyConfig& config);

}  // namespace insmc::mc
