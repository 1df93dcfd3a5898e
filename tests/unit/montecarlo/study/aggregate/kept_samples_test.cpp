// Tests for montecarlo/study/aggregate/kept_samples.h: blocks filled in any split
// and merged in any order give the same bytes as one state (and a state of
// fixed size, as the MPI reduction needs); the values come back in sample
// order, the last block cut to the study's size; the cap; the round trip.
#include "montecarlo/study/aggregate/kept_samples.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "montecarlo/study/aggregate/byte_io.h"
#include "montecarlo/study/random/philox.h"
#include "montecarlo/study/model/study_config.h"
#include "tests/unit/montecarlo/study/aggregate/permutation.h"

namespace insmc::mc {
namespace {

std::string bytes_of(const KeptSamples& k) {
  std::string out;
  k.append_to(out);
  return out;
}

// Sample i of output s has the value 1000 s + i (exact in float below 2^24).
void fill_block(KeptSamples& k, std::uint64_t samples, std::uint64_t block) {
  const std::uint64_t first = block * kBlockSize, n = std::min(kBlockSize, samples - first);
  for (std::uint64_t s = 0; s < k.outputs(); ++s) {
    float* slot = k.slot(block, s);
    for (std::uint64_t i = 0; i < n; ++i) slot[i] = static_cast<float>(1000 * s + first + i);
  }
  k.mark_filled(block);
}

TEST(KeptSamples, AnySplitMergedInAnyOrderIsTheSameBytes) {
  constexpr std::uint64_t kOutputs = 3, kSamples = 5 * kBlockSize + 77;  // 6 blocks, the last short
  KeptSamples one(kOutputs, kSamples);
  for (std::uint64_t b = 0; b < 6; ++b) fill_block(one, kSamples, b);
  const std::string expected = bytes_of(one);
  EXPECT_EQ(bytes_of(KeptSamples(kOutputs, kSamples)).size(), expected.size());  // fixed size
  CounterStream rng(31, Stream::Bootstrap, 0);
  for (int trial = 0; trial < 10; ++trial) {
    std::vector<KeptSamples> parts(1 + static_cast<std::size_t>(rng.uniform01() * 4), KeptSamples(kOutputs, kSamples));
    for (const std::size_t b : testing::permutation(6, rng))
      fill_block(parts[static_cast<std::size_t>(rng.uniform01() * static_cast<double>(parts.size()))], kSamples, b);
    KeptSamples merged;  // the empty state is the identity
    for (const std::size_t p : testing::permutation(parts.size(), rng)) merged.merge(parts[p]);
    ASSERT_EQ(bytes_of(merged), expected) << "trial " << trial;
    ASSERT_TRUE(merged == one);
  }
}

TEST(KeptSamples, ValuesComeInSampleOrderCutAtTheStudysEnd) {
  constexpr std::uint64_t kSamples = 2 * kBlockSize + 5;
  KeptSamples k(2, kSamples);
  for (std::uint64_t b = 0; b < 3; ++b) fill_block(k, kSamples, b);
  const std::vector<float> v = k.values(1);
  ASSERT_EQ(v.size(), kSamples);
  for (std::uint64_t i = 0; i < kSamples; ++i) ASSERT_EQ(v[i], static_cast<float>(1000 + i)) << i;
  // Unfilled blocks contribute nothing.
  KeptSamples partial(2, kSamples);
  fill_block(partial, kSamples, 2);
  EXPECT_EQ(partial.values(0).size(), 5u);
}

TEST(KeptSamples, TheCapKeepsTheFirstBlocksWithinTheValueBudget) {
  // 42 outputs (the default study's horizontal report rows): 2^24 values
  // are 390 whole blocks each.
  const KeptSamples big(42, 100'000'000);
  EXPECT_EQ(big.kept_blocks(), 390u);
  EXPECT_TRUE(big.keeps(389));
  EXPECT_FALSE(big.keeps(390));
  EXPECT_EQ(KeptSamples(42, 100'000).kept_blocks(), 98u);  // all of a small study
  EXPECT_EQ(KeptSamples(20000, 5000).kept_blocks(), 1u);  // at least one block
}

TEST(KeptSamples, RoundTripIsBitExactAndTruncationIsAnError) {
  constexpr std::uint64_t kSamples = 3 * kBlockSize;
  KeptSamples k(2, kSamples);
  fill_block(k, kSamples, 1);
  std::string bytes = "xy" + bytes_of(k);
  std::size_t pos = 2;
  EXPECT_TRUE(KeptSamples::read_from(bytes, pos) == k);
  EXPECT_EQ(pos, bytes.size());
  pos = 0;
  EXPECT_TRUE(KeptSamples::read_from(bytes_of(KeptSamples()), pos) == KeptSamples());
  bytes.pop_back();
  pos = 2;
  EXPECT_THROW(KeptSamples::read_from(bytes, pos), std::runtime_error);
  // A corrupt header never allocates what the bytes do not hold: 2^20
  // outputs of zero blocks, or more blocks than the bytes carry.
  for (const std::uint64_t blocks : {std::uint64_t{0}, std::uint64_t{5}}) {
    std::string corrupt;
    byte_io::put_u64(corrupt, std::uint64_t{1} << 20);
    byte_io::put_u64(corrupt, 1'000'000);
    byte_io::put_u64(corrupt, blocks);
    corrupt += std::string(64, '\0');
    pos = 0;
    EXPECT_THROW(KeptSamples::read_from(corrupt, pos), std::runtime_error) << blocks;
  }
}

}  // namespace
}  // namespace insmc::mc
