#pragma once
/// Counter-based random numbers for insmc.
///
/// Every random number drawn for a Monte Carlo sample is a pure function of
/// (seed, stream purpose, sample index, draw number), so a sample can be
/// recomputed alone (`--replay N`) and results do not depend on the thread
/// count or on which other stages draw.
///
/// Generator: Philox4x32-10 (Salmon, Moraes, Dror, Shaw, "Parallel random
/// numbers: as easy as 1, 2, 3", SC'11), written out here and pinned by the
/// published known-answer vectors and by a comparison with Random123's
/// `r123::Philox4x32` in tests/unit/montecarlo/study/random/philox_test.cpp.
///
/// Key and counter layout used by `CounterStream`:
///   key     = {seed low 32 bits, seed high 32 bits}
///   counter = {sample_index low 32, sample_index high 32, purpose, block}
/// Each Philox call ("block") yields four 32-bit words; the stream consumes
/// them in order w0, w1, w2, w3, then moves to block + 1.
///
/// None of the std:: distributions are used: their algorithms are
/// implementation-defined. The transforms below are written by hand.
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>

namespace insmc::mc {

/// 64-bit Philox key as two 32-bit words.
struct PhiloxKey {
  std::uint32_t k0;
  std::uint32_t k1;
};

/// 128-bit Philox counter / output block as four 32-bit words.
using PhiloxBlock = std::array<std::uint32_t, 4>;

/// Philox4x32 round multipliers and Weyl key increments (Salmon et al. 2011,
/// identical to Random123's PHILOX_M4x32_0/1 and PHILOX_W32_0/1).
inline constexpr std::uint32_t kPhiloxM0 = 0xD2511F53u;
inline constexpr std::uint32_t kPhiloxM1 = 0xCD9E8D57u;
inline constexpr std::uint32_t kPhiloxW0 = 0x9E3779B9u;
inline constexpr std::uint32_t kPhiloxW1 = 0xBB67AE85u;
inline constexpr int kPhiloxRounds = 10;

/// Philox4x32-10 block function: ten rounds, key bumped between rounds.
constexpr PhiloxBlock philox4x32_10(PhiloxBlock ctr, PhiloxKey key) {
  for (int round = 0; round < kPhiloxRounds; ++round) {
    if (round > 0) {
      key.k0 += kPhiloxW0;
      key.k1 += kPhiloxW1;
    }
    const std::uint64_t p0 = std::uint64_t{kPhiloxM0} * ctr[0];
    const std::uint64_t p1 = std::uint64_t{kPhiloxM1} * ctr[2];
    const auto hi0 = static_cast<std::uint32_t>(p0 >> 32);
    const auto lo0 = static_cast<std::uint32_t>(p0);
    const auto hi1 = static_cast<std::uint32_t>(p1 >> 32);
    const auto lo1 = static_cast<std::uint32_t>(p1);
    ctr = {hi1 ^ ctr[1] ^ key.k0, lo1, hi0 ^ ctr[3] ^ key.k1, lo0};
  }
  return ctr;
}

/// Stream purposes: each pipeline stage draws only from its own stream, so
/// adding a stage (e.g. sway noise) leaves the other stages' draws unchanged.
/// The numeric values are part of the reproducibility contract: never
/// renumber, only append.
enum class Stream : std::uint32_t {
  Uncertainties = 0,  ///< the uncertainty vector x of a sample
  Realignment = 1,    ///< realignment angle zeta draws
  Sway = 2,           ///< sway / vibration noise
  PulsePhase = 3,     ///< accelerometer pulse quantisation phase
  TruthEffects = 4,   ///< truth-simulator effects
  Bootstrap = 5,      ///< resampling for statistics
  Measurement = 6,    ///< measurement noise
};

/// Philox key for a 64-bit seed: {low word, high word}.
constexpr PhiloxKey philox_key(std::uint64_t seed) {
  return {static_cast<std::uint32_t>(seed), static_cast<std::uint32_t>(seed >> 32)};
}

/// Philox counter for (sample index, purpose, block number).
constexpr PhiloxBlock philox_counter(std::uint64_t sample_index, Stream purpose,
                                     std::uint32_t block) {
  return {static_cast<std::uint32_t>(sample_index),
          static_cast<std::uint32_t>(sample_index >> 32),
          static_cast<std::uint32_t>(purpose), block};
}

/// 53-bit uniform in [0, 1) from two 32-bit words: the top 53 bits of
/// (hi << 32 | lo), times 2^-53. Every value is a multiple of 2^-53.
constexpr double uniform01_from_words(std::uint32_t hi, std::uint32_t lo) {
  const std::uint64_t bits = (std::uint64_t{hi} << 32 | lo) >> 11;
  return static_cast<double>(bits) * 0x1p-53;
}

/// Uniform in the open interval (0, 1) from two 32-bit words:
/// (2k + 1) * 2^-53 with k the top 52 bits of (hi << 32 | lo). Every such
/// value is exactly representable, it is never 0 or 1 (range [2^-53,
/// 1 - 2^-53]), and 1 - u is exact and again of this form, so inverse-CDF
/// transforms can use symmetry without rounding. 52 random bits.
constexpr double open_uniform01_from_words(std::uint32_t hi, std::uint32_t lo) {
  const std::uint64_t k = (std::uint64_t{hi} << 32 | lo) >> 12;
  return static_cast<double>(2 * k + 1) * 0x1p-53;
}

/// Standard normal CDF Phi(x) = erfc(-x / sqrt 2) / 2. Relative accuracy of
/// a few ulp for x <= 0 (the lower tail); for large positive x the result
/// rounds to 1, so compute upper-tail probabilities as Phi(-x).
double normal_cdf(double x);

/// Inverse standard normal CDF, Wichura's algorithm AS 241 (PPND16), Applied
/// Statistics 37 (1988) 477-484: rational approximations with relative
/// error about 1e-16. Exact symmetry: inverse_normal_cdf(1 - p) ==
/// -inverse_normal_cdf(p) whenever 1 - p is exact (p in [0.5, 1)).
/// p must lie in [0, 1]; p = 0 and p = 1 return -inf and +inf.
double inverse_normal_cdf(double p);

/// Maps a uniform u in (0, 1) to a normal with standard deviation sigma
/// truncated to [-bound, bound], by inverting the CDF over
/// [Phi(-bound/sigma), Phi(bound/sigma)]. The lower half (u < 1/2) and the
/// upper half (u >= 1/2, via 1 - u and symmetry) are inverted in the lower
/// tail so both tails keep full relative precision. Preconditions:
/// sigma >= 0, bound >= 0 (bound may be +inf); sigma == 0 or bound == 0
/// returns 0. The result always lies in [-bound, bound]. u must lie in
/// (0, 1) (u = 0 gives -bound, which is -inf for an infinite bound); with
/// u from open_uniform01 or uniform01, T(1 - u) == -T(u) exactly.
class TruncatedNormalTransform {
 public:
  TruncatedNormalTransform(double sigma, double bound);
  double operator()(double u_open) const;

 private:
  double sigma_;
  double bound_;
  double p_lo_;   ///< Phi(-bound/sigma), dimensionless
  double width_;  ///< Phi(bound/sigma) - Phi(-bound/sigma) = erf(c/sqrt 2), dimensionless
};

/// A random stream for one (seed, purpose, sample index). Draw n of the
/// stream is 32-bit word n mod 4 of block n / 4. The double-valued draws
/// consume two words each (high word first) from the current position, so a
/// stream that only calls `uniform01` yields uniform j from words 2j, 2j+1,
/// which is what `fill_uniform01` computes in bulk.
class CounterStream {
 public:
  CounterStream(std::uint64_t seed, Stream purpose, std::uint64_t sample_index);

  /// Next 32-bit word.
  std::uint32_t next_u32() {
    if (word_ == 4) refill();
    return buffer_[word_++];
  }

  /// 53-bit uniform in [0, 1) (two words).
  double uniform01() {
    const std::uint32_t hi = next_u32();
    return uniform01_from_words(hi, next_u32());
  }

  /// Uniform in (0, 1) with 52 random bits, never 0 or 1 (two words).
  double open_uniform01() {
    const std::uint32_t hi = next_u32();
    return open_uniform01_from_words(hi, next_u32());
  }

  /// lo + (hi - lo) * uniform01(): in [lo, hi) up to rounding (two words).
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform01(); }

  /// Standard normal by inverse CDF of open_uniform01() (two words; |z| < 8.3).
  double standard_normal() { return inverse_normal_cdf(open_uniform01()); }

  /// Normal(0, sigma^2) truncated to [-bound, bound] by inverse CDF (two
  /// words). See TruncatedNormalTransform; for many draws with the same
  /// (sigma, bound) build the transform once and apply it to open_uniform01().
  double truncated_normal(double sigma, double bound) {
    return TruncatedNormalTransform(sigma, bound)(open_uniform01());
  }

  /// Number of 32-bit words drawn so far.
  std::uint64_t position() const { return 4 * next_block_ - static_cast<std::uint64_t>(4 - word_); }

  /// Moves to word `position` (next_u32() then returns word `position`).
  void seek(std::uint64_t position);

 private:
  void refill();

  PhiloxKey key_;
  PhiloxBlock counter_;           ///< word 3 is set to the block number on refill
  PhiloxBlock buffer_{};          ///< output of block next_block_ - 1
  std::uint64_t next_block_ = 0;  ///< block number the next refill generates
  int word_ = 4;                  ///< next word of buffer_ to hand out; 4 = empty
};

/// Bulk uniforms: out[i * count_per_sample + j] = the j-th uniform01() of
/// CounterStream(seed, purpose, first_index + i), bit for bit, for
/// i < n_samples and j < count_per_sample. out.size() must equal
/// count_per_sample * n_samples. On x86-64 CPUs with AVX2 a vectorised
/// kernel (8 samples at a time, one Philox counter per 64-bit lane) is
/// chosen at run time, else a scalar one; the Philox rounds are integer
/// arithmetic and the doubles are formed by exact operations, so the bits
/// do not depend on the kernel.
void fill_uniform01(std::uint64_t seed, Stream purpose, std::uint64_t first_index,
                    std::size_t count_per_sample, std::size_t n_samples, std::span<double> out);

/// The same uniforms in draw-major order: out[j * n_samples + i] = the j-th
/// uniform01() of CounterStream(seed, purpose, first_index + i). The
/// samples of one draw are contiguous, as the vectorised block products
/// take them (montecarlo/study/kernels/map_product.h).
void fill_uniform01_draw_major(std::uint64_t seed, Stream purpose, std::uint64_t first_index,
                               std::size_t count_per_sample, std::size_t n_samples, std::span<double> out);

/// The order of a bulk fill's output.
enum class UniformLayout { SampleMajor, DrawMajor };

namespace detail {
/// Bulk kernels, exposed so tests can check every available one.
enum class PhiloxKernel { Generic, Avx2, Avx512 };
bool kernel_available(PhiloxKernel kernel);
/// The kernel fill_uniform01 uses (AVX-512 if available, else AVX2, else
/// Generic). The AVX-512 kernel writes the draw-major layout itself and
/// hands the sample-major one to the AVX2 kernel.
PhiloxKernel best_kernel();
void fill_uniform01_with(PhiloxKernel kernel, std::uint64_t seed, Stream purpose,
                         std::uint64_t first_index, std::size_t count_per_sample,
                         std::size_t n_samples, std::span<double> out,
                         UniformLayout layout = UniformLayout::SampleMajor);
}  // namespace detail

}  // namespace insmc::mc
