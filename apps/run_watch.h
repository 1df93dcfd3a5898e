#pragma once
/// A study's blocks run as the command line runs them: the library's runner
/// (montecarlo/study/run/study_runner.h) with progress on stderr on rank 0
/// (apps/progress.h) and, for a checkpointed run, SIGINT and SIGTERM
/// stopping it between two blocks, followed by a checkpoint
/// (apps/interrupt.h).
#include "montecarlo/study/run/join_processes.h"
#include "montecarlo/study/run/study_runner.h"

namespace insmc::app {

/// Collective, as mc::run_study_blocks; the signal handlers are installed
/// while it runs when `stop_on_signals`.
mc::RunOutcome run_study_watched(const mc::StudyConfig& config, const mc::StudyMap& map, mc::Processes& processes,
                                mc::StudyProgress start, mc::RunPlan plan, bool stop_on_signals);

}  // namespace insmc::app
