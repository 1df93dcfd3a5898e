#include "montecarlo/study/engine/block_ranges.h"

#include <algorithm>

#include "lib/common/assert.h"
#include "montecarlo/study/model/study_config.h"

namespace insmc::mc {

BlockSet normalize(BlockSet ranges) {
  std::erase_if(ranges, [](const BlockRange& r) { return r.end <= r.begin; });
  std::sort(ranges.begin(), ranges.end(), [](const BlockRange& a, const BlockRange& b) { return a.begin < b.begin; });
  BlockSet out;
  for (const BlockRange& r : ranges) {
    if (!out.empty()) {
      INSMC_ASSERT(r.begin >= out.back().end, "block ranges [{}, {}) and [{}, {}) overlap", out.back().begin,
                   out.back().end, r.begin, r.end);
      if (r.begin == out.back().end) {
        out.back().end = r.end;
        continue;
      }
    }
    out.push_back(r);
  }
  return out;
}

std::uint64_t block_total(const BlockSet& ranges) {
  std::uint64_t n = 0;
  for (const BlockRange& r : ranges) n += r.size();
  return n;
}

std::uint64_t sample_total(const BlockSet& ranges, std::uint64_t samples) {
  std::uint64_t n = 0;
  for (const BlockRange& r : ranges) {
    const std::uint64_t first = std::min(samples, r.begin * kBlockSize);
    const std::uint64_t end = std::min(samples, r.end * kBlockSize);
    n += end - first;
  }
  return n;
}

std::vector<BlockSet> split_remaining(std::uint64_t total_blocks, const BlockSet& done, int parts) {
  INSMC_ASSERT(parts >= 1, "splitting into {} parts", parts);
  BlockSet remaining;
  std::uint64_t cursor = 0;
  for (const BlockRange& r : normalize(done)) {
    INSMC_ASSERT(r.end <= total_blocks, "finished blocks [{}, {}) beyond the study's {} blocks", r.begin, r.end,
                 total_blocks);
    if (r.begin > cursor) remaining.push_back({cursor, r.begin});
    cursor = r.end;
  }
  if (cursor < total_blocks) remaining.push_back({cursor, total_blocks});

  const std::uint64_t n = block_total(remaining);
  const auto p_count = static_cast<std::uint64_t>(parts);
  std::vector<BlockSet> shares(static_cast<std::size_t>(parts));
  std::size_t range = 0;
  std::uint64_t offset = 0;  // blocks of remaining[range] already handed out
  for (std::uint64_t p = 0; p < p_count; ++p) {
    // p·n/parts without overflow for any realistic n (n < 2^54 samples / 1024).
    std::uint64_t want = (p + 1) * n / p_count - p * n / p_count;
    while (want > 0) {
      const BlockRange& r = remaining[range];
      const std::uint64_t take = std::min(want, r.size() - offset);
      shares[static_cast<std::size_t>(p)].push_back({r.begin + offset, r.begin + offset + take});
      offset += take;
      want -= take;
      if (offset == r.size()) {
        ++range;
        offset = 0;
      }
    }
  }
  return shares;
}

BlockSet take_front(const BlockSet& share, std::uint64_t count) {
  BlockSet out;
  for (const BlockRange& r : share) {
    if (count == 0) break;
    const std::uint64_t take = std::min(count, r.size());
    out.push_back({r.begin, r.begin + take});
    count -= take;
  }
  INSMC_ASSERT(count == 0, "taking {} more blocks than the share holds", count);
  return out;
}

}  // namespace insmc::mc
