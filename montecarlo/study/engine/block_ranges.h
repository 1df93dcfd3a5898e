#pragma once
/// Which of a study's blocks are finished, and how the rest is shared out:
/// the bookkeeping of checkpoints and MPI ranks. Blocks are the engine's
/// fixed kBlockSize-sample blocks; a set of blocks is a sorted list of
/// disjoint, non-adjacent half-open ranges.
#include <cstdint>
#include <vector>

namespace insmc::mc {

/// Blocks [begin, end).
struct BlockRange {
  std::uint64_t begin = 0, end = 0;
  std::uint64_t size() const { return end - begin; }
  friend bool operator==(const BlockRange&, const BlockRange&) = default;
};
using BlockSet = std::vector<BlockRange>;

/// Sorted, with empty ranges dropped and touching ranges joined. Asserts
/// that the ranges do not overlap (a block counted twice is a bug).
BlockSet normalize(BlockSet ranges);

/// The number of blocks in `ranges`.
std::uint64_t block_total(const BlockSet& ranges);

/// Samples in the blocks `ranges` of a study of `samples` samples (the last
/// block may be partial).
std::uint64_t sample_total(const BlockSet& ranges, std::uint64_t samples);

/// The blocks of [0, total_blocks) not in `done`, split into `parts`
/// contiguous shares in block order whose sizes differ by at most one block
/// (share p holds positions [p·R/parts, (p+1)·R/parts) of the R remaining
/// blocks). A share is a BlockSet; it may be empty.
std::vector<BlockSet> split_remaining(std::uint64_t total_blocks, const BlockSet& done, int parts);

/// The first `count` blocks of `share`, in order.
BlockSet take_front(const BlockSet& share, std::uint64_t count);

}  // namespace insmc::mc
