// Tests for the cancellation hook of montecarlo/study/engine/engine.h run_blocks:
// a stop request mid-run finishes exactly a prefix [first, end) of the block
// range, and the state is that of a run of the prefix alone, so a checkpoint
// records the cut without losing or repeating a sample.
#include <gtest/gtest.h>

#include <atomic>
#include <cstdint>

#include "lib/compensation/scheme.h"
#include "montecarlo/study/engine/engine.h"

namespace insmc::mc {
namespace {

// Cheap enough for Debug + sanitizers: scheme none, one system, report times.
struct Study {
  Study() : c(config()), layout(make_layout(c)), map(c, layout) {}
  static StudyConfig config() {
    StudyConfig c;
    c.schemes = {Scheme::kNone};
    c.systems = {System::kGyrocompass};
    c.with_grid = false;
    c.samples = 40 * kBlockSize + 17;  // a partial last block
    c.seed = 99;
    return c;
  }
  StudyConfig c;
  StudyLayout layout;
  StudyMap map;
};

TEST(EngineCancellation, AStopFinishesExactlyAPrefixOfTheBlocks) {
  Study study;
  const std::uint64_t n_blocks = block_count(study.c.samples);
  for (const int threads : {1, 3}) {
    study.c.threads = threads;
    std::atomic<bool> stop{false};
    std::uint64_t end = 0;
    const auto stop_after_five_blocks = [&](std::uint64_t done) {
      if (done >= 5 * kBlockSize) stop.store(true);
    };
    const StudyAccumulator acc = run_blocks(study.c, study.map, 2, n_blocks, stop_after_five_blocks, &stop, &end);
    EXPECT_GE(end, 2u + 5u) << threads << " threads";
    EXPECT_LT(end, n_blocks) << threads << " threads";
    EXPECT_EQ(acc.outputs().front().count(), (end - 2) * kBlockSize) << threads << " threads";
    EXPECT_EQ(acc.serialize(), run_blocks(study.c, study.map, 2, end).serialize()) << threads << " threads";
  }
}

TEST(EngineCancellation, AStopBeforeTheStartRunsNothingAndNoStopRunsAll) {
  Study study;
  study.c.threads = 2;
  const std::uint64_t n_blocks = block_count(study.c.samples);
  std::atomic<bool> stop{true};
  std::uint64_t end = 99;
  const StudyAccumulator none = run_blocks(study.c, study.map, 1, n_blocks, {}, &stop, &end);
  EXPECT_EQ(end, 1u);
  EXPECT_EQ(none.outputs().front().count(), 0u);
  stop.store(false);
  const StudyAccumulator all = run_blocks(study.c, study.map, 1, n_blocks, {}, &stop, &end);
  EXPECT_EQ(end, n_blocks);
  EXPECT_EQ(all.serialize(), run_blocks(study.c, study.map, 1, n_blocks).serialize());
}

}  // namespace
}  // namespace insmc::mc
