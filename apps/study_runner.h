#pragma once
/// Runs the blocks of a study that are not yet finished: split over the
/// ranks (contiguous shares in block order), oneTBB inside each rank,
/// pausing every `checkpoint_every_s` of work and on SIGINT/SIGTERM to merge
/// the ranks' states on rank 0 and write a checkpoint. Since blocks are cut
/// exactly (engine.h) and the merge is exact, the final state is the same
/// bits however the run was split, paused, interrupted and resumed.
#include <functional>
#include <vector>

#include "apps/ranks.h"
#include "montecarlo/engine/block_ranges.h"
#include "montecarlo/engine/engine.h"

namespace insmc::app {

/// What a checkpoint records of a run's progress.
struct StudyProgress {
  mc::BlockSet done;           ///< finished blocks
  mc::StudyAccumulator state;  ///< merged over `done`
};

struct RunPlan {
  /// > 0: every rank pauses after this much work [s] for a checkpoint; 0: never.
  double checkpoint_every_s = 0;
  /// SIGINT/SIGTERM stop the run between blocks, followed by a checkpoint.
  bool stop_on_signals = false;
  /// Called on rank 0 at every pause, on interruption and at the end.
  std::function<void(const StudyProgress&)> write_checkpoint;
  /// The final state on every rank (sweeps), not only on rank 0.
  bool result_everywhere = false;
};

struct RunOutcome {
  /// Rank 0 (every rank with result_everywhere): all blocks unless interrupted.
  StudyProgress progress;
  /// The signal that interrupted the run (every rank), 0 when it finished.
  int signal = 0;
  /// The blocks each rank was given in this run, in rank order.
  std::vector<mc::BlockSet> shares;
};

/// Collective. `start`: the finished blocks and their state (a resumed
/// checkpoint; its state is needed on rank 0 only).
RunOutcome run_study_blocks(const mc::StudyConfig& config, const mc::StudyMap& map, Ranks& ranks,
                            StudyProgress start, const RunPlan& plan);

}  // namespace insmc::app
