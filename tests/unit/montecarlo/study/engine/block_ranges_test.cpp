// Tests for montecarlo/study/engine/block_ranges.h: the bookkeeping of finished
// blocks (checkpoints) and of rank shares (MPI). Every block must be run
// exactly once: shares of the remaining blocks are disjoint, cover them,
// keep block order and differ in size by at most one block.
#include "montecarlo/study/engine/block_ranges.h"

#include <gtest/gtest.h>

#include <vector>

#include "montecarlo/study/model/study_config.h"

namespace insmc::mc {
namespace {

TEST(BlockRanges, NormalizeSortsJoinsAndDropsEmptyRanges) {
  EXPECT_EQ(normalize({{5, 7}, {0, 2}, {2, 3}, {4, 4}, {7, 9}}), (BlockSet{{0, 3}, {5, 9}}));
  EXPECT_EQ(normalize({}), BlockSet{});
  EXPECT_EQ(block_total({{0, 3}, {5, 9}}), 7u);
}

TEST(BlockRanges, SampleTotalCountsAPartialLastBlock) {
  const std::uint64_t samples = 3 * kBlockSize + 10;  // 4 blocks, the last with 10 samples
  EXPECT_EQ(sample_total({{0, 4}}, samples), samples);
  EXPECT_EQ(sample_total({{1, 2}}, samples), kBlockSize);
  EXPECT_EQ(sample_total({{3, 4}}, samples), 10u);
  EXPECT_EQ(sample_total({}, samples), 0u);
}

TEST(BlockRanges, SharesCoverTheRemainingBlocksOnceInOrder) {
  struct Case {
    std::uint64_t total;
    BlockSet done;
    int parts;
  };
  const std::vector<Case> cases{{10, {}, 1},          {10, {}, 3},         {10, {{0, 4}}, 2},
                                {10, {{2, 4}, {7, 8}}, 4}, {3, {}, 5},    {5, {{0, 5}}, 2},
                                {100, {{10, 20}, {50, 90}}, 7}};
  for (const Case& c : cases) {
    const std::vector<BlockSet> shares = split_remaining(c.total, c.done, c.parts);
    ASSERT_EQ(shares.size(), static_cast<std::size_t>(c.parts));
    std::vector<int> runs(c.total, 0);
    for (const BlockRange& r : c.done)
      for (std::uint64_t b = r.begin; b < r.end; ++b) ++runs[b];
    std::uint64_t last = 0, smallest = c.total, largest = 0;
    for (const BlockSet& share : shares) {
      smallest = std::min(smallest, block_total(share));
      largest = std::max(largest, block_total(share));
      for (const BlockRange& r : share) {
        EXPECT_GE(r.begin, last) << "shares follow block order";
        last = r.end;
        for (std::uint64_t b = r.begin; b < r.end; ++b) ++runs[b];
      }
    }
    for (std::uint64_t b = 0; b < c.total; ++b) EXPECT_EQ(runs[b], 1) << "block " << b << " of case " << c.total;
    EXPECT_LE(largest - smallest, 1u);
  }
}

TEST(BlockRanges, TakeFrontFollowsTheShareAcrossRanges) {
  const BlockSet share{{2, 4}, {7, 10}};
  EXPECT_EQ(take_front(share, 0), BlockSet{});
  EXPECT_EQ(take_front(share, 1), (BlockSet{{2, 3}}));
  EXPECT_EQ(take_front(share, 3), (BlockSet{{2, 4}, {7, 8}}));
  EXPECT_EQ(take_front(share, 5), share);
}

}  // namespace
}  // namespace insmc::mc
