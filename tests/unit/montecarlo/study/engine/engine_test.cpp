// Tests for montecarlo/study/engine/engine.h: determinism (the same serialized
// state for 1, 2, 3 and 8 threads, and for a 3-way "rank" split of the
// block range merged in any order), a partial last block, the merge
// identity, serialisation, and replay (evaluate_sample of Sampler::draw
// against what the engine aggregated for the same sample index).
#include "montecarlo/study/engine/engine.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "lib/compensation/extended_vector.h"
#include "lib/compensation/scheme.h"
#include "montecarlo/study/sampler/sampler.h"

namespace insmc::mc {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

// Sizes are chosen for the Debug + sanitizer build, where building a
// study's maps costs seconds per scheme and system and a block of the test
// run schemes about a second.
//
// The full sample path: schemes none, 5.1.1 (test run + realignment draws)
// and 5.4 (alignment-phase data), sway on, so the quantized measurements and
// every random stream are on the block path; one system; 3 blocks, the last
// partial (2 full + 300).
StudyConfig full_path_study() {
  StudyConfig c;
  c.schemes = {Scheme::kNone, Scheme::k5_1_1, Scheme::k5_4};
  c.systems = {System::kGyrocompass};
  c.fidelity = Fidelity::kLinear;
  c.with_grid = false;
  c.test.sway.velocity_rms_mps = 0.01;
  c.samples = 2 * kBlockSize + 300;
  c.seed = 0x5eed'0000'1234ULL;
  c.threads = 1;
  return c;
}

// A cheap study: scheme none, both systems, report times only.
StudyConfig cheap_study() {
  StudyConfig c = full_path_study();
  c.schemes = {Scheme::kNone};
  c.systems = {System::kTheodolite, System::kGyrocompass};
  return c;
}

// Layout and map built once per config (StudyMap keeps pointers to both).
struct Study {
  explicit Study(const StudyConfig& config) : c(config), layout(make_layout(c)), map(c, layout) {}
  StudyConfig c;
  StudyLayout layout;
  StudyMap map;
  StudyAccumulator run(std::uint64_t first, std::uint64_t end) const { return run_blocks(c, map, first, end); }
  StudyAccumulator run_all() const { return run(0, block_count(c.samples)); }
};

void expect_same_bytes_for_any_thread_count(Study& study) {
  study.c.threads = 1;
  const std::string expected = study.run_all().serialize();
  for (const int threads : {2, 3, 8}) {
    study.c.threads = threads;
    EXPECT_EQ(study.run_all().serialize(), expected) << threads << " threads";
  }
}

// ---------------------------------------------------------------- determinism

TEST(EngineDeterminism, ThreadCountDoesNotChangeTheBytes) {
  Study study(full_path_study());
  ASSERT_EQ(block_count(study.c.samples), 3u);
  expect_same_bytes_for_any_thread_count(study);
}

TEST(EngineDeterminism, ThreadCountDoesNotChangeTheBytesPaperWithGrid) {
  StudyConfig c = cheap_study();
  c.fidelity = Fidelity::kPaper;
  c.with_grid = true;  // the envelope grid too: 47 times
  Study study(c);
  expect_same_bytes_for_any_thread_count(study);
}

TEST(EngineDeterminism, RankSplitMergedInAnyOrderEqualsTheSingleRun) {
  Study study(full_path_study());
  study.c.threads = 2;
  const std::uint64_t n_blocks = block_count(study.c.samples);
  ASSERT_EQ(n_blocks, 3u);
  const std::string expected = study.run_all().serialize();
  // Three "ranks" of one block each; the last holds the partial block.
  const std::array<StudyAccumulator, 3> parts{study.run(0, 1), study.run(1, 2), study.run(2, n_blocks)};
  std::array<int, 3> order{0, 1, 2};
  do {
    StudyAccumulator total;  // default-constructed: the merge identity
    for (const int p : order) total.merge(parts[static_cast<std::size_t>(p)]);
    EXPECT_EQ(total.serialize(), expected) << "order " << order[0] << order[1] << order[2];
  } while (std::next_permutation(order.begin(), order.end()));
  // A tree: p0 + (p2 + p1).
  StudyAccumulator right = parts[2];
  right.merge(parts[1]);
  StudyAccumulator tree = parts[0];
  tree.merge(right);
  EXPECT_EQ(tree.serialize(), expected);
  // Through serialisation, as ranks would exchange states.
  StudyAccumulator via_bytes = StudyAccumulator::deserialize(parts[1].serialize());
  via_bytes.merge(StudyAccumulator::deserialize(parts[0].serialize()));
  via_bytes.merge(StudyAccumulator::deserialize(parts[2].serialize()));
  EXPECT_EQ(via_bytes.serialize(), expected);
}

TEST(EngineDeterminism, MergeWithAnEmptyAccumulatorIsTheIdentity) {
  Study study(cheap_study());
  const StudyAccumulator acc = study.run(0, 2);
  StudyAccumulator left;
  left.merge(acc);
  StudyAccumulator right = acc;
  right.merge(StudyAccumulator{});
  StudyAccumulator zero_samples = acc;
  zero_samples.merge(study.run(2, 2));  // an empty block range
  EXPECT_EQ(left.serialize(), acc.serialize());
  EXPECT_EQ(right.serialize(), acc.serialize());
  EXPECT_EQ(zero_samples.serialize(), acc.serialize());
}

// ---------------------------------------------------------------- blocks

TEST(Engine, PartialLastBlockCountsEverySampleOnce) {
  Study study(cheap_study());
  const std::uint64_t n_blocks = block_count(study.c.samples);
  const StudyAccumulator all = study.run_all();
  const StudyAccumulator last = study.run(n_blocks - 1, n_blocks);
  ASSERT_EQ(all.outputs().size(), study.layout.outputs.size());
  for (std::size_t o = 0; o < all.outputs().size(); ++o) {
    EXPECT_EQ(all.outputs()[o].count(), study.c.samples) << "output " << o;
    EXPECT_EQ(last.outputs()[o].count(), 300u) << "output " << o;
  }
  // A study of fewer samples than one block.
  study.c.samples = 5;
  const StudyAccumulator t = study.run_all();
  for (const OutputStats& s : t.outputs()) EXPECT_EQ(s.count(), 5u);
}

TEST(Engine, SerializeRoundTrip) {
  Study study(cheap_study());
  const StudyAccumulator acc = study.run(0, 2);
  const std::string bytes = acc.serialize();
  const StudyAccumulator back = StudyAccumulator::deserialize(bytes);
  EXPECT_TRUE(back == acc);
  EXPECT_EQ(back.serialize(), bytes);
  EXPECT_THROW(StudyAccumulator::deserialize(bytes.substr(0, bytes.size() - 1)), std::runtime_error);
  EXPECT_THROW(StudyAccumulator::deserialize(bytes + "x"), std::runtime_error);
  EXPECT_THROW(StudyAccumulator::deserialize("not a state"), std::runtime_error);
  EXPECT_THROW(StudyAccumulator::deserialize(""), std::runtime_error);
}

// ---------------------------------------------------------------- replay

// A bound on how far evaluate_sample could differ from the engine's value
// for the same extended vector z if the two summed in different orders: each
// output row r = s·z is a sum of z_slot::kDim products, within gamma_kDim
// sum_i |s_i z_i| of the exact value (Higham 3.1); the horizontal output
// adds the two rows' bounds and a rounding of the sqrt. Since the block
// kernel (map_product.h) sums every sample alike the values are in fact the
// same bits (EverySampleOfABlockHasTheReplayedBitsInEveryScheme); these
// tests keep the bound, which would hold for any summation order.
std::vector<double> replay_tolerances(const Study& study, std::uint64_t index, const UncertaintyVector& x) {
  constexpr double kGamma = z_slot::kDim * kEps / (1 - z_slot::kDim * kEps);
  const Eigen::MatrixXd xm = x;
  Eigen::MatrixXd z(z_slot::kDim, 1);
  std::vector<Eigen::VectorXd> row_bound;
  for (std::size_t j = 0; j < study.c.systems.size(); ++j) {
    const int sj = static_cast<int>(j);
    study.map.pipeline(sj).extended_vectors(index, 1, xm, z);
    row_bound.push_back(study.map.transposed(sj).cwiseAbs().transpose() * z.col(0).cwiseAbs());
  }
  std::vector<double> tol;
  for (std::size_t o = 0; o < study.layout.outputs.size(); ++o) {
    const Eigen::VectorXd& rb = row_bound[static_cast<std::size_t>(study.map.system_index(o))];
    const int base = study.map.row_base(o);
    const Axis axis = study.layout.outputs[o].axis;
    const double b = axis == Axis::kHorizontal ? rb[base + 3] + rb[base + 4] : rb[base + static_cast<int>(axis)];
    tol.push_back(2 * kGamma * b * (1 + 4 * kEps) + 4 * kEps * b);
  }
  return tol;
}

TEST(EngineReplay, OneSampleBlockMatchesEvaluateSample) {
  // samples = 1024 k + 1 makes block k hold sample 1024 k alone: the
  // engine's min and max of every output are then that sample's value. The
  // engine builds z with the same call as evaluate_sample (one sample), so
  // the quantized measurements of the test-run schemes are comparable too.
  Study study(full_path_study());
  const Sampler sampler(study.c.uncertainties);
  for (const std::uint64_t k : {0u, 1u, 6u, 1000u}) {
    study.c.samples = k * kBlockSize + 1;
    const StudyAccumulator acc = study.run(k, k + 1);
    const std::uint64_t index = k * kBlockSize;
    const UncertaintyVector x = sampler.draw(study.c.seed, index);
    const std::vector<double> replay = evaluate_sample(study.c, study.map, study.layout, index, x);
    const std::vector<double> tol = replay_tolerances(study, index, x);
    ASSERT_EQ(replay.size(), acc.outputs().size());
    for (std::size_t o = 0; o < replay.size(); ++o) {
      const OutputSummary s = acc.outputs()[o].summarize(study.c.confidence);
      ASSERT_EQ(s.n, 1u);
      EXPECT_EQ(s.min, s.max) << "output " << o;
      EXPECT_NEAR(s.min, replay[o], tol[o]) << "block " << k << " output " << o;
    }
  }
}

TEST(EngineReplay, EverySampleOfABlockHasTheReplayedBitsInEveryScheme) {
  // The block products are a pure function of each sample (map_product.h):
  // the observations of the test run, hence the pulse counts, and the
  // outputs are the same bits in a block of 1024 or of one, for every
  // scheme. So a full block's min and max are exactly the replayed extremes,
  // and so is an odd-sized block's (whose last sample Eigen once summed in
  // another order).
  for (const std::uint64_t samples : {5 * kBlockSize, 4 * kBlockSize + 7}) {
    StudyConfig c = full_path_study();
    c.samples = samples;
    Study study(c);
    const Sampler sampler(study.c.uncertainties);
    constexpr std::uint64_t kBlockIndex = 4;
    const StudyAccumulator acc = study.run(kBlockIndex, kBlockIndex + 1);
    const std::size_t n_out = study.layout.outputs.size();
    std::vector<double> lo(n_out, std::numeric_limits<double>::infinity());
    std::vector<double> hi(n_out, -std::numeric_limits<double>::infinity());
    for (std::uint64_t i = kBlockIndex * kBlockSize; i < samples; ++i) {
      const std::vector<double> r = evaluate_sample(study.c, study.map, study.layout, i, sampler.draw(study.c.seed, i));
      for (std::size_t o = 0; o < n_out; ++o) lo[o] = std::min(lo[o], r[o]), hi[o] = std::max(hi[o], r[o]);
    }
    for (std::size_t o = 0; o < n_out; ++o) {
      const OutputSummary s = acc.outputs()[o].summarize(study.c.confidence);
      ASSERT_EQ(s.n, samples - kBlockIndex * kBlockSize);
      EXPECT_EQ(s.min, lo[o]) << samples << " samples, output " << o;
      EXPECT_EQ(s.max, hi[o]) << samples << " samples, output " << o;
    }
  }
}

TEST(EngineReplay, FullBlockMinMaxAndSumOfSquaresMatchEvaluateSample) {
  // Schemes none and 5.4 only, within the rounding bound above. (The
  // test-run schemes' pulse counters could move by a whole pulse under a
  // different summation order, which no rounding bound covers; with the
  // block kernel they are the same bits: EverySampleOfABlock... above.)
  StudyConfig c = full_path_study();
  c.schemes = {Scheme::kNone, Scheme::k5_4};
  Study study(c);
  const Sampler sampler(study.c.uncertainties);
  constexpr std::uint64_t kBlockIndex = 4;
  const StudyAccumulator acc = study.run(kBlockIndex, kBlockIndex + 1);
  const std::size_t n_out = study.layout.outputs.size();
  std::vector<double> lo(n_out, std::numeric_limits<double>::infinity());
  std::vector<double> hi(n_out, -std::numeric_limits<double>::infinity());
  std::vector<double> tol(n_out, 0.0), sum_sq(n_out, 0.0), sum_sq_tol(n_out, 0.0);
  for (std::uint64_t i = kBlockIndex * kBlockSize; i < (kBlockIndex + 1) * kBlockSize; ++i) {
    const UncertaintyVector x = sampler.draw(study.c.seed, i);
    const std::vector<double> r = evaluate_sample(study.c, study.map, study.layout, i, x);
    const std::vector<double> t = replay_tolerances(study, i, x);
    for (std::size_t o = 0; o < n_out; ++o) {
      lo[o] = std::min(lo[o], r[o]);
      hi[o] = std::max(hi[o], r[o]);
      tol[o] = std::max(tol[o], t[o]);
      sum_sq[o] += r[o] * r[o];
      sum_sq_tol[o] += 2 * std::fabs(r[o]) * t[o] + t[o] * t[o];
    }
  }
  // The min (max) of values each within tol moves by at most tol. The sum of
  // squares: per-sample bounds above, plus two recursive summations of 1024
  // positive terms (1024 eps relative each).
  constexpr double kSumTol = 2 * (kBlockSize + 4) * kEps;
  for (std::size_t o = 0; o < n_out; ++o) {
    const OutputStats& s = acc.outputs()[o];
    const OutputSummary sum = s.summarize(study.c.confidence);
    EXPECT_EQ(sum.n, kBlockSize);
    EXPECT_NEAR(sum.min, lo[o], tol[o]) << "output " << o;
    EXPECT_NEAR(sum.max, hi[o], tol[o]) << "output " << o;
    EXPECT_NEAR(s.sum_squares(), sum_sq[o], sum_sq_tol[o] + kSumTol * sum_sq[o]) << "output " << o;
  }
}

}  // namespace
}  // namespace insmc::mc
