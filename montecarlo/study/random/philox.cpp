#include "montecarlo/study/random/philox.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "lib/common/assert.h"

#if defined(__GNUC__) && defined(__x86_64__)
#include <immintrin.h>
#endif

namespace insmc::mc {

double normal_cdf(double x) { return 0.5 * std::erfc(-x / std::numbers::sqrt2); }

double inverse_normal_cdf(double p) {
  // Wichura, AS 241 PPND16 (Appl. Statist. 37 (1988) 477-484). Coefficients
  // as published; the same values appear in R's qnorm.c.
  INSMC_ASSERT(p >= 0.0 && p <= 1.0, "inverse_normal_cdf: p = {} outside [0, 1]", p);
  if (p == 0.0) return -std::numeric_limits<double>::infinity();
  if (p == 1.0) return std::numeric_limits<double>::infinity();

  const double q = p - 0.5;
  if (std::fabs(q) <= 0.425) {
    // Central region, |q| <= 0.425: r = 0.180625 - q^2.
    const double r = 0.180625 - q * q;
    const double num =
        (((((((2.5090809287301226727e+3 * r + 3.3430575583588128105e+4) * r +
              6.7265770927008700853e+4) * r + 4.5921953931549871457e+4) * r +
            1.3731693765509461125e+4) * r + 1.9715909503065514427e+3) * r +
          1.3314166789178437745e+2) * r + 3.3871328727963666080e+0);
    const double den =
        (((((((5.2264952788528545610e+3 * r + 2.8729085735721942674e+4) * r +
              3.9307895800092710610e+4) * r + 2.1213794301586595867e+4) * r +
            5.3941960214247511077e+3) * r + 6.8718700749205790830e+2) * r +
          4.2313330701600911252e+1) * r + 1.0);
    return q * num / den;
  }

  // Tails: r = sqrt(-log(min(p, 1 - p))); 1 - p is exact for p >= 0.5.
  double r = std::sqrt(-std::log(q < 0.0 ? p : 1.0 - p));
  double val = 0.0;
  if (r <= 5.0) {
    // min(p, 1 - p) >= exp(-25) ~ 1.4e-11.
    r -= 1.6;
    const double num =
        (((((((7.74545014278341407640e-4 * r + 2.27238449892691845833e-2) * r +
              2.41780725177450611770e-1) * r + 1.27045825245236838258e+0) * r +
            3.64784832476320460504e+0) * r + 5.76949722146069140550e+0) * r +
          4.63033784615654529590e+0) * r + 1.42343711074968357734e+0);
    const double den =
        (((((((1.05075007164441684324e-9 * r + 5.47593808499534494600e-4) * r +
              1.51986665636164571966e-2) * r + 1.48103976427480074590e-1) * r +
            6.89767334985100004550e-1) * r + 1.67638483018380384940e+0) * r +
          2.05319162663775882187e+0) * r + 1.0);
    val = num / den;
  } else {
    // Far tails.
    r -= 5.0;
    const double num =
        (((((((2.01033439929228813265e-7 * r + 2.71155556874348757815e-5) * r +
              1.24266094738807843860e-3) * r + 2.65321895265761230930e-2) * r +
            2.96560571828504891230e-1) * r + 1.78482653991729133580e+0) * r +
          5.46378491116411436990e+0) * r + 6.65790464350110377720e+0);
    const double den =
        (((((((2.04426310338993978564e-15 * r + 1.42151175831644588870e-7) * r +
              1.84631831751005468180e-5) * r + 7.86869131145613259100e-4) * r +
            1.48753612908506148525e-2) * r + 1.36929880922735805310e-1) * r +
          5.99832206555887937690e-1) * r + 1.0);
    val = num / den;
  }
  return q < 0.0 ? -val : val;
}

TruncatedNormalTransform::TruncatedNormalTransform(double sigma, double bound)
    : sigma_(sigma), bound_(bound), p_lo_(0.0), width_(1.0) {
  INSMC_ASSERT(sigma >= 0.0 && bound >= 0.0,
               "truncated normal: sigma = {}, bound = {}; both must be >= 0", sigma, bound);
  if (sigma > 0.0 && bound > 0.0) {
    const double c = bound / sigma;  // dimensionless half-width in sigmas
    p_lo_ = 0.5 * std::erfc(c / std::numbers::sqrt2);
    width_ = std::erf(c / std::numbers::sqrt2);
  }
}

double TruncatedNormalTransform::operator()(double u_open) const {
  if (sigma_ == 0.0 || bound_ == 0.0) return 0.0;
  // Invert in the lower tail for both halves: T(1 - u) = -T(u) exactly.
  const bool upper = u_open >= 0.5;
  const double u_lower = upper ? 1.0 - u_open : u_open;
  const double z = inverse_normal_cdf(p_lo_ + u_lower * width_);
  const double x = std::clamp(sigma_ * z, -bound_, bound_);
  return upper ? -x : x;
}

CounterStream::CounterStream(std::uint64_t seed, Stream purpose, std::uint64_t sample_index)
    : key_(philox_key(seed)), counter_(philox_counter(sample_index, purpose, 0)) {}

void CounterStream::refill() {
  INSMC_ASSERT(next_block_ <= std::numeric_limits<std::uint32_t>::max(),
               "CounterStream: more than 2^34 words drawn from one stream");
  counter_[3] = static_cast<std::uint32_t>(next_block_);
  buffer_ = philox4x32_10(counter_, key_);
  ++next_block_;
  word_ = 0;
}

void CounterStream::seek(std::uint64_t position) {
  next_block_ = position / 4;
  const int word = static_cast<int>(position % 4);
  if (word == 0) {
    word_ = 4;  // generate lazily on the next draw
  } else {
    refill();
    word_ = word;
  }
}

namespace {

// Arguments shared by the bulk kernels (validated by fill_uniform01_with).
struct BulkRequest {
  PhiloxKey key;
  std::uint32_t purpose;
  std::uint64_t first_index;
  std::size_t count;    ///< uniforms per sample
  std::size_t samples;  ///< n_samples
  double* out;          ///< count * samples doubles
  bool draw_major;      ///< out[j * samples + i] (else out[i * count + j])
  /// Where uniform j of sample i (counted from first_index) goes.
  std::size_t at(std::size_t i, std::size_t j) const { return draw_major ? j * samples + i : i * count + j; }
};

// ------------------------------------------------------------- generic kernel

// Number of counters processed together by the generic kernel.
constexpr std::size_t kGenericLanes = 16;

struct LaneBlock {
  alignas(64) std::uint32_t w0[kGenericLanes];
  alignas(64) std::uint32_t w1[kGenericLanes];
  alignas(64) std::uint32_t w2[kGenericLanes];
  alignas(64) std::uint32_t w3[kGenericLanes];
};

// One scalar block function per lane; the independent lanes give the CPU
// instruction-level parallelism. (Measured on x86-64 with GCC 12, SSE2
// vectorisation of this loop is slower than scalar code: the 32x32->64
// multiplies need shuffles around pmuludq.)
void philox_lanes_generic(LaneBlock& b, PhiloxKey key) {
  for (std::size_t l = 0; l < kGenericLanes; ++l) {
    const PhiloxBlock out = philox4x32_10({b.w0[l], b.w1[l], b.w2[l], b.w3[l]}, key);
    b.w0[l] = out[0];
    b.w1[l] = out[1];
    b.w2[l] = out[2];
    b.w3[l] = out[3];
  }
}

void fill_generic(const BulkRequest& r) {
  // Each block yields two uniforms (words 0,1 and words 2,3); with an odd
  // count the last block of each sample yields one. Blocks are enumerated
  // sample by sample, block by block, which is also the order of their
  // uniforms in `out`, so the output is written sequentially.
  const std::size_t blocks_per_sample = (r.count + 1) / 2;
  const bool odd = r.count % 2 != 0;
  const std::size_t total_blocks = blocks_per_sample * r.samples;
  std::size_t sample = 0;  // counted from first_index
  std::size_t block = 0;
  LaneBlock b;
  bool single[kGenericLanes];  // lane yields one uniform (last block, odd count)
  std::size_t lane_sample[kGenericLanes], lane_block[kGenericLanes];
  for (std::size_t start = 0; start < total_blocks; start += kGenericLanes) {
    const std::size_t lanes = std::min(kGenericLanes, total_blocks - start);
    for (std::size_t l = 0; l < lanes; ++l) {
      const std::uint64_t index = r.first_index + sample;
      b.w0[l] = static_cast<std::uint32_t>(index);
      b.w1[l] = static_cast<std::uint32_t>(index >> 32);
      b.w2[l] = r.purpose;
      b.w3[l] = static_cast<std::uint32_t>(block);
      single[l] = odd && block + 1 == blocks_per_sample;
      lane_sample[l] = sample;
      lane_block[l] = block;
      if (++block == blocks_per_sample) {
        block = 0;
        ++sample;
      }
    }
    for (std::size_t l = lanes; l < kGenericLanes; ++l) {  // unused tail lanes
      b.w0[l] = b.w1[l] = b.w2[l] = b.w3[l] = 0;
    }
    philox_lanes_generic(b, r.key);
    for (std::size_t l = 0; l < lanes; ++l) {
      r.out[r.at(lane_sample[l], 2 * lane_block[l])] = uniform01_from_words(b.w0[l], b.w1[l]);
      if (!single[l]) r.out[r.at(lane_sample[l], 2 * lane_block[l] + 1)] = uniform01_from_words(b.w2[l], b.w3[l]);
    }
  }
}

// ---------------------------------------------------------------- AVX2 kernel

#if defined(__GNUC__) && defined(__x86_64__)
#define INSMC_PHILOX_HAVE_AVX2_KERNEL 1

// Layout. Lanes run over consecutive samples at the same block number: a
// "group" is 4 samples, one Philox counter per 64-bit lane of a __m256i,
// and a tile is kGroups groups (4 * kGroups consecutive samples). For each
// block number b the tile's counters differ only in the sample index, so
//  - the first three Philox rounds are partly the same for every block of
//    a sample and are computed once per tile (make_group), which saves a
//    fifth of the multiplies, and
//  - block b of 4 samples yields columns 2b and 2b+1 of 4 rows of `out`,
//    written with a 2x2 transpose and four 16-byte stores.
// Word representation: each Philox word sits in the low 32 bits of a 64-bit
// lane; the high 32 bits hold garbage that is never used (vpmuludq reads
// only the low 32 bits, so the low half of a 64-bit product *is* the
// wrapping 32-bit product, and the high half is moved down by a dword
// shuffle). All arithmetic is integer, so the bits equal philox4x32_10's.
// Doubles: (hi << 32 | lo) >> 11 times 2^-53 equals
//   (hi * 2^-32 - 1/2) + (1/2 + (lo >> 11) * 2^-53)
// where the first term is the double with high dword 0x41300000 (2^20) and
// low dword hi, minus 2^20 + 1/2, and the second the double with high dword
// 0x3FE00000 (1/2) and low dword lo >> 11: both operations are exact (the
// difference is a multiple of 2^-32 below 1/2 in magnitude, the sum a
// multiple of 2^-53 below 1), so the result is bit-identical to
// uniform01_from_words.
// Measured for the engine's call (33 uniforms x 1024 samples, GCC 12,
// one core of a Sapphire Rapids Xeon at ~2.8 GHz): 5.7e8 doubles/s, against
// 1.6e8 for the generic kernel and 1.9e8 for the earlier compiler-vectorised
// AVX2 lane loop. The limit is the vector ports (8 ops per 4 counters per
// round: 2 vpmuludq, 2 vpshufd, 4 vpxor), not the multiply latency.
namespace avx2 {

// Groups of 4 samples per tile. Measured: 1 group is ~8% slower, 3 or 4
// groups are no faster than 2.
constexpr int kGroups = 2;
constexpr std::size_t kTileSamples = 4 * kGroups;

#define INSMC_AVX2 [[gnu::target("avx2"), gnu::always_inline]] inline

INSMC_AVX2 __m256i xor_(__m256i a, __m256i b) { return _mm256_xor_si256(a, b); }
// High 32 bits of each 64-bit lane moved to the low 32 bits.
INSMC_AVX2 __m256i high(__m256i p) { return _mm256_shuffle_epi32(p, 0xB1); }

struct Keys {
  __m256i m0, m1;             ///< multipliers
  __m256i k0[kPhiloxRounds];  ///< round keys
  __m256i k1[kPhiloxRounds];
};

// Per-tile values that do not depend on the block number (names after the
// round that produces them; c0..c3 are the counter words).
struct Group {
  __m256i h0;  ///< round 0: c2 = h0 ^ block
  __m256i a2;  ///< round 1: c2
  __m256i d2;  ///< round 1: c3
  __m256i q1;  ///< round 2: M1 * c2 (its low half is round 2's c1)
  __m256i e2;  ///< round 2: c0 = (round 1 c1) ^ e2
  __m256i f2;  ///< round 2: c2 = hi(M0 * c0) ^ f2
};

// Rounds 0-2 as far as they do not depend on the block number b, for
// samples index .. index + 3. A round maps c to
// (hi p1 ^ c1 ^ K0, lo p1, hi p0 ^ c3 ^ K1, lo p0) with p0 = M0 c0,
// p1 = M1 c2. Starting from c = (idx lo, idx hi, purpose, b):
//   round 0: p0 = M0 idx lo, p1 = M1 purpose (the same for all lanes);
//            only c2 = (hi p0 ^ K1[0]) ^ b depends on b.
//   round 1: p0 = M0 c0 does not depend on b, so c2 and c3 do not;
//            p1 = M1 c2 does (run_block).
//   round 2: p1 = M1 c2 does not depend on b, so c1 does not; c0 and c2
//            are a per-block value xor a per-sample one (e2, f2).
INSMC_AVX2 Group make_group(const Keys& k, std::uint64_t index, std::uint32_t purpose) {
  const __m256i idx = _mm256_add_epi64(_mm256_set1_epi64x(static_cast<long long>(index)),
                                       _mm256_setr_epi64x(0, 1, 2, 3));
  const __m256i idx_hi = _mm256_srli_epi64(idx, 32);
  const std::uint64_t p1 = std::uint64_t{kPhiloxM1} * purpose;
  const __m256i p1_hi = _mm256_set1_epi32(static_cast<int>(static_cast<std::uint32_t>(p1 >> 32)));
  Group g;
  // round 0
  const __m256i p0 = _mm256_mul_epu32(idx, k.m0);
  const __m256i a1 = xor_(xor_(p1_hi, idx_hi), k.k0[0]);
  g.h0 = xor_(high(p0), k.k1[0]);
  // round 1 (its c0 and c1 depend on b: run_block)
  const __m256i q0 = _mm256_mul_epu32(a1, k.m0);
  g.a2 = xor_(xor_(high(q0), p0), k.k1[1]);
  g.d2 = q0;
  // round 2
  g.q1 = _mm256_mul_epu32(g.a2, k.m1);
  g.e2 = xor_(high(g.q1), k.k0[2]);
  g.f2 = xor_(g.d2, k.k1[2]);
  return g;
}

// The four output words (low 32 bits of each lane) of block `b` for the
// 4 samples of each group.
struct Words {
  __m256i c0, c1, c2, c3;
};

// Block b (broadcast in bv) of all groups of a tile; the groups advance in
// lockstep, round by round, so their independent multiply chains overlap.
INSMC_AVX2 void run_block(const Keys& k, const Group (&g)[kGroups], __m256i c1_key, __m256i bv,
                          Words (&w)[kGroups]) {
#pragma GCC unroll 8
  for (int q = 0; q < kGroups; ++q) {
    // round 1: p1 = M1 * (h0 ^ b), c0 = hi p1 ^ c1_key, c1 = p1
    const __m256i p = _mm256_mul_epu32(xor_(g[q].h0, bv), k.m1);
    w[q].c1 = p;
    w[q].c0 = xor_(high(p), c1_key);
  }
#pragma GCC unroll 8
  for (int q = 0; q < kGroups; ++q) {
    // round 2: p0 = M0 * c0, p1 = q1
    const __m256i r = _mm256_mul_epu32(w[q].c0, k.m0);
    w[q].c0 = xor_(w[q].c1, g[q].e2);
    w[q].c1 = g[q].q1;
    w[q].c2 = xor_(high(r), g[q].f2);
    w[q].c3 = r;
  }
#pragma GCC unroll 8
  for (int round = 3; round < kPhiloxRounds; ++round) {
#pragma GCC unroll 8
    for (int q = 0; q < kGroups; ++q) {
      const __m256i p0 = _mm256_mul_epu32(w[q].c0, k.m0);
      const __m256i p1 = _mm256_mul_epu32(w[q].c2, k.m1);
      w[q].c0 = xor_(high(p1), xor_(w[q].c1, k.k0[round]));
      w[q].c1 = p1;
      w[q].c2 = xor_(high(p0), xor_(w[q].c3, k.k1[round]));
      w[q].c3 = p0;
    }
  }
}

// uniform01_from_words(hi, lo) for the low 32 bits of each 64-bit lane.
INSMC_AVX2 __m256d to_uniform(__m256i hi, __m256i lo) {
  const __m256i two20 = _mm256_set1_epi64x(0x4130000000000000);  // 2^20
  const __m256i half = _mm256_set1_epi64x(0x3FE0000000000000);   // 1/2
  const __m256d t = _mm256_sub_pd(_mm256_castsi256_pd(_mm256_blend_epi32(hi, two20, 0xAA)),
                                  _mm256_set1_pd(0x1p20 + 0.5));
  const __m256d u =
      _mm256_castsi256_pd(_mm256_blend_epi32(_mm256_srli_epi32(lo, 11), half, 0xAA));
  return _mm256_add_pd(t, u);
}

// Writes columns col (even) and, if `both`, col + 1 of rows row .. row + 3
// (a row is one sample, `stride` doubles). e / o hold the 4 rows' values of
// the two columns. `rows` < 4 writes only the first rows (tile tail).
template <bool kFull>
INSMC_AVX2 void store_pair(double* row, std::size_t stride, __m256d e, __m256d o, bool both,
                           int rows) {
  const __m256d lo = _mm256_unpacklo_pd(e, o);  // rows 0 and 2
  const __m256d hi = _mm256_unpackhi_pd(e, o);  // rows 1 and 3
  if constexpr (kFull) {
    const __m128d v[4] = {_mm256_castpd256_pd128(lo), _mm256_castpd256_pd128(hi),
                          _mm256_extractf128_pd(lo, 1), _mm256_extractf128_pd(hi, 1)};
    if (both) {
      for (int s = 0; s < 4; ++s) _mm_storeu_pd(row + s * stride, v[s]);
    } else {
      for (int s = 0; s < 4; ++s) _mm_storel_pd(row + s * stride, v[s]);
    }
  } else {
    alignas(32) double ev[4];
    alignas(32) double ov[4];
    _mm256_storeu_pd(ev, e);
    _mm256_storeu_pd(ov, o);
    for (int s = 0; s < rows; ++s) {
      row[s * stride] = ev[s];
      if (both) row[s * stride + 1] = ov[s];
    }
  }
}

// Writes the 4 samples' values of one draw to run[0..3] (draw-major
// layout), or the first `rows` of them (tile tail).
template <bool kFull>
INSMC_AVX2 void store_run(double* run, __m256d v, int rows) {
  if constexpr (kFull) {
    _mm256_storeu_pd(run, v);
  } else {
    alignas(32) double values[4];
    _mm256_storeu_pd(values, v);
    for (int s = 0; s < rows; ++s) run[s] = values[s];
  }
}

// One tile: samples first .. first + rows - 1 (rows <= kTileSamples; the
// lanes beyond `rows` are computed and dropped), written to dst (row 0).
template <bool kFull>
[[gnu::target("avx2")]] void fill_tile(const Keys& k, __m256i c1_key, const BulkRequest& r,
                                       std::uint64_t first, double* dst, int rows) {
  Group g[kGroups];
  for (int q = 0; q < kGroups; ++q) g[q] = make_group(k, first + 4 * q, r.purpose);
  const std::size_t stride = r.count;
  const std::size_t full_blocks = r.count / 2;  // blocks yielding two uniforms
  std::size_t b = 0;
  for (; b < full_blocks; ++b) {
    const __m256i bv = _mm256_set1_epi32(static_cast<int>(static_cast<std::uint32_t>(b)));
    Words w[kGroups];
    run_block(k, g, c1_key, bv, w);
    for (int q = 0; q < kGroups; ++q) {
      if (!kFull && rows <= 4 * q) break;
      const __m256d e = to_uniform(w[q].c0, w[q].c1), o = to_uniform(w[q].c2, w[q].c3);
      if (r.draw_major) {
        store_run<kFull>(dst + 2 * b * r.samples + 4 * q, e, std::min(4, rows - 4 * q));
        store_run<kFull>(dst + (2 * b + 1) * r.samples + 4 * q, o, std::min(4, rows - 4 * q));
      } else {
        store_pair<kFull>(dst + 4 * q * stride + 2 * b, stride, e, o, true, std::min(4, rows - 4 * q));
      }
    }
  }
  if (r.count % 2 != 0) {  // last block: one uniform (words 0, 1)
    const __m256i bv = _mm256_set1_epi32(static_cast<int>(static_cast<std::uint32_t>(b)));
    Words w[kGroups];
    run_block(k, g, c1_key, bv, w);
    for (int q = 0; q < kGroups; ++q) {
      if (!kFull && rows <= 4 * q) break;
      const __m256d e = to_uniform(w[q].c0, w[q].c1);
      if (r.draw_major)
        store_run<kFull>(dst + 2 * b * r.samples + 4 * q, e, std::min(4, rows - 4 * q));
      else
        store_pair<kFull>(dst + 4 * q * stride + 2 * b, stride, e, e, false, std::min(4, rows - 4 * q));
    }
  }
}

[[gnu::target("avx2")]] void fill(const BulkRequest& r) {
  Keys k;
  k.m0 = _mm256_set1_epi64x(kPhiloxM0);
  k.m1 = _mm256_set1_epi64x(kPhiloxM1);
  PhiloxKey key = r.key;
  for (int round = 0; round < kPhiloxRounds; ++round) {
    if (round > 0) {
      key.k0 += kPhiloxW0;
      key.k1 += kPhiloxW1;
    }
    k.k0[round] = _mm256_set1_epi32(static_cast<int>(key.k0));
    k.k1[round] = _mm256_set1_epi32(static_cast<int>(key.k1));
  }
  // Round 1's c0 = hi(p1) ^ c1 ^ K0[1] with c1 = lo(M1 * purpose) from round 0.
  const std::uint64_t p1 = std::uint64_t{kPhiloxM1} * r.purpose;
  const __m256i c1_key = _mm256_set1_epi32(
      static_cast<int>(static_cast<std::uint32_t>(p1) ^ (r.key.k0 + kPhiloxW0)));

  std::size_t i = 0;
  for (; i + kTileSamples <= r.samples; i += kTileSamples)
    fill_tile<true>(k, c1_key, r, r.first_index + i, r.out + r.at(i, 0), 4 * kGroups);
  if (i < r.samples)
    fill_tile<false>(k, c1_key, r, r.first_index + i, r.out + r.at(i, 0), static_cast<int>(r.samples - i));
}

#undef INSMC_AVX2

}  // namespace avx2

// -------------------------------------------------------------- AVX-512 kernel

// The AVX2 kernel's rounds on 8 samples a lane group (one Philox counter
// per 64-bit lane of a __m512i), for the draw-major layout only: block b of
// a group yields draws 2b and 2b+1 of 8 consecutive samples, each one
// contiguous 64-byte store. The same integer arithmetic and the same exact
// double formation as the AVX2 kernel (see there), so the same bits. The
// sample-major layout, which needs a transpose per store, stays on AVX2.
#define INSMC_PHILOX_HAVE_AVX512_KERNEL 1
// GCC 12's AVX-512 intrinsics start their masked forms from an undefined
// vector and then report it as maybe uninitialized (GCC bug 105593).
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
namespace avx512 {

constexpr int kGroups = 2;
constexpr std::size_t kTileSamples = 8 * kGroups;

#define INSMC_AVX512 [[gnu::target("avx512f"), gnu::always_inline]] inline

INSMC_AVX512 __m512i xor_(__m512i a, __m512i b) { return _mm512_xor_si512(a, b); }
INSMC_AVX512 __m512i high(__m512i p) { return _mm512_shuffle_epi32(p, static_cast<_MM_PERM_ENUM>(0xB1)); }

struct Keys {
  __m512i m0, m1;
  __m512i k0[kPhiloxRounds];
  __m512i k1[kPhiloxRounds];
};

struct Group {
  __m512i h0, a2, d2, q1, e2, f2;  // as avx2::Group
};

// avx2::make_group for samples index .. index + 7.
INSMC_AVX512 Group make_group(const Keys& k, std::uint64_t index, std::uint32_t purpose) {
  const __m512i idx = _mm512_add_epi64(_mm512_set1_epi64(static_cast<long long>(index)),
                                       _mm512_set_epi64(7, 6, 5, 4, 3, 2, 1, 0));
  const __m512i idx_hi = _mm512_srli_epi64(idx, 32);
  const std::uint64_t p1 = std::uint64_t{kPhiloxM1} * purpose;
  const __m512i p1_hi = _mm512_set1_epi32(static_cast<int>(static_cast<std::uint32_t>(p1 >> 32)));
  Group g;
  const __m512i p0 = _mm512_mul_epu32(idx, k.m0);
  const __m512i a1 = xor_(xor_(p1_hi, idx_hi), k.k0[0]);
  g.h0 = xor_(high(p0), k.k1[0]);
  const __m512i q0 = _mm512_mul_epu32(a1, k.m0);
  g.a2 = xor_(xor_(high(q0), p0), k.k1[1]);
  g.d2 = q0;
  g.q1 = _mm512_mul_epu32(g.a2, k.m1);
  g.e2 = xor_(high(g.q1), k.k0[2]);
  g.f2 = xor_(g.d2, k.k1[2]);
  return g;
}

struct Words {
  __m512i c0, c1, c2, c3;
};

// avx2::run_block on 8-sample groups.
INSMC_AVX512 void run_block(const Keys& k, const Group (&g)[kGroups], __m512i c1_key, __m512i bv,
                            Words (&w)[kGroups]) {
#pragma GCC unroll 8
  for (int q = 0; q < kGroups; ++q) {
    const __m512i p = _mm512_mul_epu32(xor_(g[q].h0, bv), k.m1);
    w[q].c1 = p;
    w[q].c0 = xor_(high(p), c1_key);
  }
#pragma GCC unroll 8
  for (int q = 0; q < kGroups; ++q) {
    const __m512i r = _mm512_mul_epu32(w[q].c0, k.m0);
    w[q].c0 = xor_(w[q].c1, g[q].e2);
    w[q].c1 = g[q].q1;
    w[q].c2 = xor_(high(r), g[q].f2);
    w[q].c3 = r;
  }
#pragma GCC unroll 8
  for (int round = 3; round < kPhiloxRounds; ++round) {
#pragma GCC unroll 8
    for (int q = 0; q < kGroups; ++q) {
      const __m512i p0 = _mm512_mul_epu32(w[q].c0, k.m0);
      const __m512i p1 = _mm512_mul_epu32(w[q].c2, k.m1);
      w[q].c0 = xor_(high(p1), xor_(w[q].c1, k.k0[round]));
      w[q].c1 = p1;
      w[q].c2 = xor_(high(p0), xor_(w[q].c3, k.k1[round]));
      w[q].c3 = p0;
    }
  }
}

// avx2::to_uniform on 8 lanes.
INSMC_AVX512 __m512d to_uniform(__m512i hi, __m512i lo) {
  const __m512i two20 = _mm512_set1_epi64(0x4130000000000000);
  const __m512i half = _mm512_set1_epi64(0x3FE0000000000000);
  const __m512d t = _mm512_sub_pd(_mm512_castsi512_pd(_mm512_mask_blend_epi32(0xAAAA, hi, two20)),
                                  _mm512_set1_pd(0x1p20 + 0.5));
  const __m512d u = _mm512_castsi512_pd(_mm512_mask_blend_epi32(0xAAAA, _mm512_srli_epi32(lo, 11), half));
  return _mm512_add_pd(t, u);
}

// The 8 samples' values of one draw at run[0..7], or the first `rows`.
template <bool kFull>
INSMC_AVX512 void store_run(double* run, __m512d v, int rows) {
  if constexpr (kFull) {
    _mm512_storeu_pd(run, v);
  } else {
    _mm512_mask_storeu_pd(run, static_cast<__mmask8>((1u << rows) - 1), v);
  }
}

template <bool kFull>
[[gnu::target("avx512f")]] void fill_tile(const Keys& k, __m512i c1_key, const BulkRequest& r, std::uint64_t first,
                                          double* dst, int rows) {
  Group g[kGroups];
  for (int q = 0; q < kGroups; ++q) g[q] = make_group(k, first + 8 * q, r.purpose);
  const std::size_t blocks = (r.count + 1) / 2;
  for (std::size_t b = 0; b < blocks; ++b) {
    const __m512i bv = _mm512_set1_epi32(static_cast<int>(static_cast<std::uint32_t>(b)));
    Words w[kGroups];
    run_block(k, g, c1_key, bv, w);
    const bool second = 2 * b + 1 < r.count;  // an odd count's last block yields one uniform
    for (int q = 0; q < kGroups; ++q) {
      if (!kFull && rows <= 8 * q) break;
      const int group_rows = std::min(8, rows - 8 * q);
      store_run<kFull>(dst + 2 * b * r.samples + 8 * q, to_uniform(w[q].c0, w[q].c1), group_rows);
      if (second) store_run<kFull>(dst + (2 * b + 1) * r.samples + 8 * q, to_uniform(w[q].c2, w[q].c3), group_rows);
    }
  }
}

[[gnu::target("avx512f")]] void fill(const BulkRequest& r) {
  Keys k;
  k.m0 = _mm512_set1_epi64(kPhiloxM0);
  k.m1 = _mm512_set1_epi64(kPhiloxM1);
  PhiloxKey key = r.key;
  for (int round = 0; round < kPhiloxRounds; ++round) {
    if (round > 0) {
      key.k0 += kPhiloxW0;
      key.k1 += kPhiloxW1;
    }
    k.k0[round] = _mm512_set1_epi32(static_cast<int>(key.k0));
    k.k1[round] = _mm512_set1_epi32(static_cast<int>(key.k1));
  }
  const std::uint64_t p1 = std::uint64_t{kPhiloxM1} * r.purpose;
  const __m512i c1_key = _mm512_set1_epi32(
      static_cast<int>(static_cast<std::uint32_t>(p1) ^ (r.key.k0 + kPhiloxW0)));
  std::size_t i = 0;
  for (; i + kTileSamples <= r.samples; i += kTileSamples)
    fill_tile<true>(k, c1_key, r, r.first_index + i, r.out + r.at(i, 0), 8 * kGroups);
  if (i < r.samples)
    fill_tile<false>(k, c1_key, r, r.first_index + i, r.out + r.at(i, 0), static_cast<int>(r.samples - i));
}

#undef INSMC_AVX512

}  // namespace avx512
#pragma GCC diagnostic pop
#endif

}  // namespace

namespace detail {

bool kernel_available(PhiloxKernel kernel) {
  switch (kernel) {
    case PhiloxKernel::Generic:
      return true;
    case PhiloxKernel::Avx2:
#ifdef INSMC_PHILOX_HAVE_AVX2_KERNEL
      return __builtin_cpu_supports("avx2");
#else
      return false;
#endif
    case PhiloxKernel::Avx512:
#ifdef INSMC_PHILOX_HAVE_AVX512_KERNEL
      // Its sample-major layout is the AVX2 kernel's.
      return __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx2");
#else
      return false;
#endif
  }
  return false;
}

PhiloxKernel best_kernel() {
  static const PhiloxKernel best = kernel_available(PhiloxKernel::Avx512) ? PhiloxKernel::Avx512
                                   : kernel_available(PhiloxKernel::Avx2)   ? PhiloxKernel::Avx2
                                                                            : PhiloxKernel::Generic;
  return best;
}

void fill_uniform01_with(PhiloxKernel kernel, std::uint64_t seed, Stream purpose,
                         std::uint64_t first_index, std::size_t count_per_sample,
                         std::size_t n_samples, std::span<double> out, UniformLayout layout) {
  INSMC_ASSERT(out.size() == count_per_sample * n_samples,
               "fill_uniform01: out.size() = {}, expected {} x {}", out.size(), count_per_sample,
               n_samples);
  if (count_per_sample == 0 || n_samples == 0) return;
  INSMC_ASSERT((count_per_sample + 1) / 2 - 1 <= std::numeric_limits<std::uint32_t>::max(),
               "fill_uniform01: {} uniforms per sample exceed one stream", count_per_sample);
  INSMC_ASSERT(kernel_available(kernel), "Philox kernel {} not available",
               static_cast<int>(kernel));
  const BulkRequest request{philox_key(seed), static_cast<std::uint32_t>(purpose), first_index,
                            count_per_sample, n_samples, out.data(), layout == UniformLayout::DrawMajor};
  switch (kernel) {
    case PhiloxKernel::Generic:
      fill_generic(request);
      return;
    case PhiloxKernel::Avx2:
#ifdef INSMC_PHILOX_HAVE_AVX2_KERNEL
      avx2::fill(request);
#endif
      return;
    case PhiloxKernel::Avx512:
#ifdef INSMC_PHILOX_HAVE_AVX512_KERNEL
      if (request.draw_major)
        avx512::fill(request);
      else
        avx2::fill(request);
#endif
      return;
  }
}

}  // namespace detail

void fill_uniform01(std::uint64_t seed, Stream purpose, std::uint64_t first_index,
                    std::size_t count_per_sample, std::size_t n_samples, std::span<double> out) {
  detail::fill_uniform01_with(detail::best_kernel(), seed, purpose, first_index, count_per_sample,
                              n_samples, out, UniformLayout::SampleMajor);
}

void fill_uniform01_draw_major(std::uint64_t seed, Stream purpose, std::uint64_t first_index,
                               std::size_t count_per_sample, std::size_t n_samples, std::span<double> out) {
  detail::fill_uniform01_with(detail::best_kernel(), seed, purpose, first_index, count_per_sample,
                              n_samples, out, UniformLayout::DrawMajor);
}

}  // namespace insmc::mc
