#pragma once
/// Runs the blocks of a study that are not yet finished: split over the
/// ranks (contiguous shares in block order), oneTBB inside each rank,
/// pausing every `checkpoint_every_s` of work and on SIGINT/SIGTERM to merge
/// the ranks' states on rank 0 and write a checkpoint. Since blocks are cut
/// exactly (engine.h) and the merge is exact, the final state is the same
/// bits however the run was split, paused, interrupted and resumed.
#include <atomic>
#include <cstdint>
#include <functional>
#include <vector>

#include "montecarlo/study/engine/block_ranges.h"
#include "montecarlo/study/engine/engine.h"
#include "montecarlo/study/run/processes.h"

namespace insmc::mc {

/// What a checkpoint records of a run's progress.
struct StudyProgress {
  BlockSet done;           ///< finished blocks
  StudyAccumulator state;  ///< merged over `done`
};

/// What the caller shows and hears while the blocks run: the command line's
/// progress line and signal handlers (apps/run_watch.h). The defaults watch
/// nothing and never stop the run.
class RunWatch {
 public:
  virtual ~RunWatch() = default;
  /// Rank 0, before the first block: the samples of its share in this run.
  virtual void start(std::uint64_t samples) { (void)samples; }
  /// Rank 0: the samples of its share done so far; called from the
  /// engine's threads.
  virtual void progress(std::uint64_t done) { (void)done; }
  /// A flag that something outside the run (a signal handler) sets to stop
  /// it between two blocks, followed by a checkpoint; the run sets and
  /// clears it too, to pause for its checkpoints. Null: nothing outside
  /// stops the run.
  virtual std::atomic<bool>* stop_flag() { return nullptr; }
  /// Why the flag was set from outside: a signal number, 0 when it was not.
  virtual int stop_signal() const { return 0; }
};

struct RunPlan {
  /// > 0: every rank pauses after this much work [s] for a checkpoint; 0: never.
  double checkpoint_every_s = 0;
  /// Progress and outside stops (SIGINT/SIGTERM); null: none.
  RunWatch* watch = nullptr;
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
  std::vector<BlockSet> shares;
};

/// Collective. `start`: the finished blocks and their state (a resumed
/// checkpoint; its state is needed on rank 0 only).
RunOutcome run_study_blocks(const StudyConfig& config, const StudyMap& map, Processes& processes, StudyProgress start,
                            const RunPlan& plan);

}  // namespace insmc::mc
