#include "montecarlo/study/run/study_runner.h"

#include <algorithm>
#include <atomic>
#include <chrono>

namespace insmc::mc {

RunOutcome run_study_blocks(const StudyConfig& c, const StudyMap& map, Processes& processes, StudyProgress start,
                            const RunPlan& plan) {
  using Clock = std::chrono::steady_clock;
  RunOutcome out;
  out.shares = split_remaining(block_count(c.samples), start.done, processes.size());
  const BlockSet& mine = out.shares[static_cast<std::size_t>(processes.rank())];
  const std::uint64_t my_blocks = block_total(mine);

  RunWatch no_watch;
  RunWatch& watch = plan.watch != nullptr ? *plan.watch : no_watch;
  std::atomic<bool> own_pause{false};
  std::atomic<bool>& pause = watch.stop_flag() != nullptr ? *watch.stop_flag() : own_pause;
  const auto signal = [&] { return watch.stop_signal(); };
  const bool root = processes.root();
  if (root) watch.start(sample_total(mine, c.samples));

  const double every_s = std::min(plan.checkpoint_every_s, 1e9);  // ~30 years: no overflow in ns
  const auto every = std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(every_s));
  Clock::time_point deadline = plan.checkpoint_every_s > 0 ? Clock::now() + every : Clock::time_point::max();
  StudyAccumulator local(map);  // this rank's blocks of this run
  std::uint64_t finished = 0;   // blocks of `mine` finished, a prefix in share order
  for (;;) {
    // Work until the share is finished, a checkpoint is due or a signal came.
    while (finished < my_blocks && !pause.load()) {
      std::uint64_t skip = finished;
      std::size_t i = 0;
      while (skip >= mine[i].size()) skip -= mine[i++].size();
      const std::uint64_t first = mine[i].begin + skip;
      const std::uint64_t samples_before = sample_total(take_front(mine, finished), c.samples);
      const auto on_block = [&](std::uint64_t samples_done) {
        if (root) watch.progress(samples_before + samples_done);
        if (Clock::now() >= deadline) pause.store(true);
      };
      std::uint64_t end = first;
      local.merge(run_blocks(c, map, first, mine[i].end, on_block, &pause, &end));  // moved in
      finished += end - first;
    }
    const std::vector<std::int64_t> status = processes.max_all({signal(), finished < my_blocks ? 1 : 0});
    const bool complete = status[1] == 0, interrupted = status[0] != 0 && !complete;
    if (complete || plan.write_checkpoint) {
      StudyAccumulator merged = processes.merge(local, complete && plan.result_everywhere);
      const std::vector<std::uint64_t> counts = processes.gather(finished);
      if (processes.root() || (complete && plan.result_everywhere)) {
        out.progress.state = start.state;
        out.progress.state.merge(std::move(merged));
      }
      if (processes.root()) {
        BlockSet done = start.done;
        for (std::size_t r = 0; r < counts.size(); ++r) {
          const BlockSet part = take_front(out.shares[r], counts[r]);
          done.insert(done.end(), part.begin(), part.end());
        }
        out.progress.done = normalize(std::move(done));
        if (plan.write_checkpoint) plan.write_checkpoint(out.progress);
      }
    }
    if (interrupted) out.signal = static_cast<int>(status[0]);
    if (complete || interrupted) return out;
    deadline = plan.checkpoint_every_s > 0 ? Clock::now() + every : Clock::time_point::max();
    pause.store(false);
    if (signal() != 0) pause.store(true);  // a signal that came while resetting
  }
}

}  // namespace insmc::mc
