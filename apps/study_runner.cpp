#include "apps/study_runner.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <optional>

#include "apps/interrupt.h"
#include "apps/progress.h"

namespace insmc::app {

RunOutcome run_study_blocks(const mc::StudyConfig& c, const mc::StudyMap& map, Ranks& ranks, StudyProgress start,
                            const RunPlan& plan) {
  using Clock = std::chrono::steady_clock;
  RunOutcome out;
  out.shares = mc::split_remaining(mc::block_count(c.samples), start.done, ranks.size());
  const mc::BlockSet& mine = out.shares[static_cast<std::size_t>(ranks.rank())];
  const std::uint64_t my_blocks = mc::block_total(mine);

  std::atomic<bool> pause{false};
  std::optional<InterruptGuard> guard;
  if (plan.stop_on_signals) guard.emplace(pause);
  const auto signal = [&] { return guard ? InterruptGuard::signal_received() : 0; };
  std::optional<Progress> progress;
  if (ranks.root()) progress.emplace(mc::sample_total(mine, c.samples));

  const double every_s = std::min(plan.checkpoint_every_s, 1e9);  // ~30 years: no overflow in ns
  const auto every = std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(every_s));
  Clock::time_point deadline = plan.checkpoint_every_s > 0 ? Clock::now() + every : Clock::time_point::max();
  mc::StudyAccumulator local(map);  // this rank's blocks of this run
  std::uint64_t finished = 0;       // blocks of `mine` finished, a prefix in share order
  for (;;) {
    // Work until the share is finished, a checkpoint is due or a signal came.
    while (finished < my_blocks && !pause.load()) {
      std::uint64_t skip = finished;
      std::size_t i = 0;
      while (skip >= mine[i].size()) skip -= mine[i++].size();
      const std::uint64_t first = mine[i].begin + skip;
      const std::uint64_t samples_before = mc::sample_total(mc::take_front(mine, finished), c.samples);
      const auto on_block = [&](std::uint64_t samples_done) {
        if (progress) progress->update(samples_before + samples_done);
        if (Clock::now() >= deadline) pause.store(true);
      };
      std::uint64_t end = first;
      local.merge(mc::run_blocks(c, map, first, mine[i].end, on_block, &pause, &end));  // moved in
      finished += end - first;
    }
    const std::vector<std::int64_t> status = ranks.max_all({signal(), finished < my_blocks ? 1 : 0});
    const bool complete = status[1] == 0, interrupted = status[0] != 0 && !complete;
    if (complete || plan.write_checkpoint) {
      mc::StudyAccumulator merged = ranks.merge(local, complete && plan.result_everywhere);
      const std::vector<std::uint64_t> counts = ranks.gather(finished);
      if (ranks.root() || (complete && plan.result_everywhere)) {
        out.progress.state = start.state;
        out.progress.state.merge(std::move(merged));
      }
      if (ranks.root()) {
        mc::BlockSet done = start.done;
        for (std::size_t r = 0; r < counts.size(); ++r) {
          const mc::BlockSet part = mc::take_front(out.shares[r], counts[r]);
          done.insert(done.end(), part.begin(), part.end());
        }
        out.progress.done = mc::normalize(std::move(done));
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

}  // namespace insmc::app
