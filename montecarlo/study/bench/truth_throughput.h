#pragma once
/// The `truth` path of `insmc bench`: `insmc run --fidelity truth` (the
/// nonlinear simulator per sample and system, scheme none, report times)
/// against its floor, the hand-written integrator of the same equations
/// (truth_reference.h) on the same samples, pulse phases and threads, with
/// a plain parallel loop around it. Both are measured in the same call so
/// that their ratio survives a noisy machine.
#include <cstdint>

#include "montecarlo/study/model/study_config.h"

namespace insmc::mc {

struct TruthThroughput {
  double reference_samples_per_s;  ///< hand-written integrator, `threads` threads
  double truth_samples_per_s;      ///< run_blocks on the truth study, `threads` threads
};

/// Scheme none, systems 1 and 2, the report times (no grid), fidelity truth.
StudyConfig truth_study(std::uint64_t samples, int threads);

TruthThroughput measure_truth_throughput(const StudyConfig& config);

}  // namespace insmc::mc
