// Tests for montecarlo/study/random/philox.h: the Philox4x32-10 block function
// (published known answers and Random123 as an independent reference), the
// counter layout of CounterStream, bulk == scalar bits, the uniform
// transforms, the inverse normal CDF against an erfc-based reference, and
// Kolmogorov-Smirnov tests of the samplers with power companions.
#include "montecarlo/study/random/philox.h"

#include <gtest/gtest.h>

#include <Random123/philox.h>
#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <functional>
#include <iostream>
#include <limits>
#include <numbers>
#include <random>
#include <span>
#include <string>
#include <vector>

namespace insmc::mc {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

// One 32-bit word from mt19937 (its output sequence is fixed by the standard).
std::uint32_t w32(std::mt19937& g) { return static_cast<std::uint32_t>(g()); }

// ---------------------------------------------------------------- Philox

struct KnownAnswer {
  PhiloxBlock ctr;
  PhiloxKey key;
  PhiloxBlock expected;
};

// Random123 kat_vectors, philox4x32_10 lines (the three standard cases).
constexpr std::array<KnownAnswer, 3> kKnownAnswers{{
    {{0, 0, 0, 0}, {0, 0}, {0x6627e8d5u, 0xe169c58du, 0xbc57ac4cu, 0x9b00dbd8u}},
    {{0xffffffffu, 0xffffffffu, 0xffffffffu, 0xffffffffu},
     {0xffffffffu, 0xffffffffu},
     {0x408f276du, 0x41c83b0eu, 0xa20bc7c6u, 0x6d5451fdu}},
    {{0x243f6a88u, 0x85a308d3u, 0x13198a2eu, 0x03707344u},
     {0xa4093822u, 0x299f31d0u},
     {0xd16cfe09u, 0x94fdccebu, 0x5001e420u, 0x24126ea1u}},
}};

TEST(Philox, KnownAnswerVectors) {
  for (const auto& kat : kKnownAnswers) {
    EXPECT_EQ(philox4x32_10(kat.ctr, kat.key), kat.expected)
        << std::hex << "ctr " << kat.ctr[0] << " " << kat.ctr[1] << " " << kat.ctr[2] << " "
        << kat.ctr[3] << " key " << kat.key.k0 << " " << kat.key.k1;
  }
}

TEST(Philox, IsConstexpr) {
  static_assert(philox4x32_10({0, 0, 0, 0}, {0, 0})[0] == 0x6627e8d5u);
  SUCCEED();
}

PhiloxBlock random123_philox(const PhiloxBlock& ctr, const PhiloxKey& key) {
  r123::Philox4x32 rng;
  r123::Philox4x32::ctr_type c = {{ctr[0], ctr[1], ctr[2], ctr[3]}};
  r123::Philox4x32::key_type k = {{key.k0, key.k1}};
  const auto r = rng(c, k);
  return {r[0], r[1], r[2], r[3]};
}

TEST(Philox, MatchesRandom123ForRandomInputs) {
  static_assert(std::is_same_v<r123::Philox4x32, r123::Philox4x32_R<10>>);
  std::mt19937 words(20240601u);  // engine output is fixed by the standard
  constexpr int kCases = 20000;
  for (int i = 0; i < kCases; ++i) {
    const PhiloxBlock ctr{w32(words), w32(words), w32(words), w32(words)};
    const PhiloxKey key{w32(words), w32(words)};
    ASSERT_EQ(philox4x32_10(ctr, key), random123_philox(ctr, key)) << "case " << i;
  }
}

// ---------------------------------------------------------------- stream layout

TEST(CounterStream, WordsFollowDocumentedCounterLayout) {
  constexpr std::uint64_t kSeed = 0x0123456789abcdefull;
  constexpr std::uint64_t kIndex = 0xfedcba9876543210ull;
  CounterStream s(kSeed, Stream::Sway, kIndex);
  for (std::uint32_t block = 0; block < 5; ++block) {
    const PhiloxBlock expected = random123_philox(
        {0x76543210u, 0xfedcba98u, static_cast<std::uint32_t>(Stream::Sway), block},
        {0x89abcdefu, 0x01234567u});
    for (int w = 0; w < 4; ++w) EXPECT_EQ(s.next_u32(), expected[w]) << "block " << block;
  }
  EXPECT_EQ(s.position(), 20u);
}

TEST(CounterStream, StreamEnumValuesArePinned) {
  // Part of the reproducibility contract: renumbering changes every result.
  EXPECT_EQ(static_cast<std::uint32_t>(Stream::Uncertainties), 0u);
  EXPECT_EQ(static_cast<std::uint32_t>(Stream::Realignment), 1u);
  EXPECT_EQ(static_cast<std::uint32_t>(Stream::Sway), 2u);
  EXPECT_EQ(static_cast<std::uint32_t>(Stream::PulsePhase), 3u);
  EXPECT_EQ(static_cast<std::uint32_t>(Stream::TruthEffects), 4u);
  EXPECT_EQ(static_cast<std::uint32_t>(Stream::Bootstrap), 5u);
  EXPECT_EQ(static_cast<std::uint32_t>(Stream::Measurement), 6u);
}

TEST(CounterStream, DeterministicAndSeparatedByKey) {
  const auto first_words = [](std::uint64_t seed, Stream s, std::uint64_t index) {
    CounterStream cs(seed, s, index);
    std::vector<std::uint32_t> w(16);
    for (auto& x : w) x = cs.next_u32();
    return w;
  };
  const auto base = first_words(7, Stream::Uncertainties, 3);
  EXPECT_EQ(base, first_words(7, Stream::Uncertainties, 3));
  EXPECT_NE(base, first_words(8, Stream::Uncertainties, 3));
  EXPECT_NE(base, first_words(7 + (1ull << 32), Stream::Uncertainties, 3));
  EXPECT_NE(base, first_words(7, Stream::Realignment, 3));
  EXPECT_NE(base, first_words(7, Stream::Uncertainties, 4));
  EXPECT_NE(base, first_words(7, Stream::Uncertainties, 3 + (1ull << 32)));
}

TEST(CounterStream, SeekMatchesSequentialDraws) {
  CounterStream sequential(11, Stream::Bootstrap, 99);
  std::vector<std::uint32_t> words(41);
  for (auto& w : words) w = sequential.next_u32();
  for (std::uint64_t pos = 0; pos < 40; ++pos) {
    CounterStream s(11, Stream::Bootstrap, 99);
    s.seek(pos);
    EXPECT_EQ(s.position(), pos);
    EXPECT_EQ(s.next_u32(), words[pos]) << "position " << pos;
    EXPECT_EQ(s.next_u32(), words[pos + 1]) << "position " << pos + 1;
    EXPECT_EQ(s.position(), pos + 2);
  }
}

TEST(CounterStream, DoubleDrawsUseTwoWordsHighFirst) {
  CounterStream words(5, Stream::PulsePhase, 12);
  CounterStream draws(5, Stream::PulsePhase, 12);
  for (int i = 0; i < 9; ++i) {  // odd count: draws straddle blocks too
    const std::uint32_t hi = words.next_u32();
    const std::uint32_t lo = words.next_u32();
    EXPECT_EQ(draws.uniform01(), uniform01_from_words(hi, lo));
  }
  draws.next_u32();
  words.next_u32();
  const std::uint32_t hi = words.next_u32();
  const std::uint32_t lo = words.next_u32();
  EXPECT_EQ(draws.standard_normal(), inverse_normal_cdf(open_uniform01_from_words(hi, lo)));
}

// ---------------------------------------------------------------- bulk == scalar

TEST(FillUniform01, EqualsScalarStreamBitForBit) {
  // The AVX2 kernel runs tiles of 8 samples (lanes over samples, rounds 0-2
  // partly shared by a sample's blocks), so the cases cover partial tiles,
  // odd and even counts, every purpose word (it enters round 0), a sample
  // index crossing into the high word inside a tile, wrap-around past
  // 2^64 in the dropped lanes of a partial tile, and the engine's call
  // (33 uniforms x 1024 samples).
  struct Case {
    std::uint64_t seed;
    Stream purpose;
    std::uint64_t first_index;
    std::size_t count_per_sample;
    std::size_t n_samples;
  };
  const std::array<Case, 13> cases{{
      {1, Stream::Uncertainties, 0, 1, 1},
      {1, Stream::Realignment, 0, 2, 1},
      {2, Stream::Sway, 5, 3, 7},
      {3, Stream::PulsePhase, 100, 7, 17},
      {4, Stream::TruthEffects, 0, 16, 16},
      {5, Stream::Bootstrap, (1ull << 32) - 3, 5, 9},  // index crosses into the high word
      {6, Stream::Measurement, 12345, 33, 5},
      {0xffffffffffffffffull, Stream::Uncertainties, 0xfffffffffffffff0ull, 31, 15},
      {9, Stream::Sway, 77, 128, 3},
      {10, Stream::Uncertainties, 7ull << 20, 33, 1024},
      {11, Stream::Measurement, 999, 33, 13},
      {0x0123456789abcdefull, Stream::Realignment, 0xfedcba9876543210ull, 34, 11},
      {12, static_cast<Stream>(0xfffffff0u), (1ull << 32) - 5, 9, 8},
  }};
  using detail::PhiloxKernel;
  int kernels_tested = 0;
  for (const PhiloxKernel kernel : {PhiloxKernel::Generic, PhiloxKernel::Avx2, PhiloxKernel::Avx512}) {
    if (!detail::kernel_available(kernel)) continue;
    ++kernels_tested;
    for (const UniformLayout layout : {UniformLayout::SampleMajor, UniformLayout::DrawMajor})
      for (const Case& c : cases) {
        std::vector<double> bulk(c.count_per_sample * c.n_samples, -1.0);
        detail::fill_uniform01_with(kernel, c.seed, c.purpose, c.first_index, c.count_per_sample,
                                    c.n_samples, bulk, layout);
        for (std::size_t i = 0; i < c.n_samples; ++i) {
          CounterStream s(c.seed, c.purpose, c.first_index + i);
          for (std::size_t j = 0; j < c.count_per_sample; ++j) {
            const double scalar = s.uniform01();
            const std::size_t at =
                layout == UniformLayout::DrawMajor ? j * c.n_samples + i : i * c.count_per_sample + j;
            ASSERT_EQ(std::bit_cast<std::uint64_t>(bulk[at]), std::bit_cast<std::uint64_t>(scalar))
                << "kernel " << static_cast<int>(kernel) << " layout " << static_cast<int>(layout)
                << " seed " << c.seed << " purpose " << static_cast<std::uint32_t>(c.purpose)
                << " sample " << i << " draw " << j;
          }
        }
      }
  }
  EXPECT_GE(kernels_tested, 1);
  if (!detail::kernel_available(PhiloxKernel::Avx2)) {
    std::cout << "note: no AVX2 on this CPU; only the generic bulk kernel was tested\n";
  }
}

TEST(FillUniform01, EveryBulkKernelAndLayoutMatchesRandom123) {
  // Uniform j of sample i is uniform01_from_words of words 2(j mod 2)..+1 of
  // Random123's Philox4x32-10 at counter {i lo, i hi, purpose, j / 2}.
  using detail::PhiloxKernel;
  const std::uint64_t seed = 0x9e3779b97f4a7c15ull, first = (1ull << 32) - 9;
  const std::size_t count = 43, n = 37;
  for (const PhiloxKernel kernel : {PhiloxKernel::Generic, PhiloxKernel::Avx2, PhiloxKernel::Avx512}) {
    if (!detail::kernel_available(kernel)) continue;
    for (const UniformLayout layout : {UniformLayout::SampleMajor, UniformLayout::DrawMajor}) {
      std::vector<double> bulk(count * n);
      detail::fill_uniform01_with(kernel, seed, Stream::Uncertainties, first, count, n, bulk, layout);
      for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = 0; j < count; ++j) {
          const std::uint64_t index = first + i;
          const PhiloxBlock w = random123_philox(
              {static_cast<std::uint32_t>(index), static_cast<std::uint32_t>(index >> 32), 0u,
               static_cast<std::uint32_t>(j / 2)},
              philox_key(seed));
          const double want = j % 2 == 0 ? uniform01_from_words(w[0], w[1]) : uniform01_from_words(w[2], w[3]);
          const std::size_t at = layout == UniformLayout::DrawMajor ? j * n + i : i * count + j;
          ASSERT_EQ(bulk[at], want) << "kernel " << static_cast<int>(kernel) << " sample " << i << " draw " << j;
        }
    }
  }
}

TEST(FillUniform01, WritesExactlyItsSpan) {
  // Partial tiles must not write outside out: guard values on both sides.
  using detail::PhiloxKernel;
  for (const PhiloxKernel kernel : {PhiloxKernel::Generic, PhiloxKernel::Avx2, PhiloxKernel::Avx512}) {
    if (!detail::kernel_available(kernel)) continue;
    for (const std::size_t count : {std::size_t{1}, std::size_t{2}, std::size_t{33}}) {
      for (std::size_t n = 1; n <= 17; ++n)
        for (const UniformLayout layout : {UniformLayout::SampleMajor, UniformLayout::DrawMajor}) {
        std::vector<double> buf(count * n + 2 * count + 2, -7.0);
        detail::fill_uniform01_with(kernel, 3, Stream::Sway, 40, count, n,
                                    std::span<double>(buf).subspan(count + 1, count * n), layout);
        for (std::size_t i = 0; i < buf.size(); ++i) {
          const bool inside = i >= count + 1 && i < count + 1 + count * n;
          if (inside) {
            ASSERT_TRUE(buf[i] >= 0.0 && buf[i] < 1.0) << "count " << count << " n " << n;
          } else {
            ASSERT_EQ(buf[i], -7.0) << "kernel " << static_cast<int>(kernel) << " count "
                                    << count << " n " << n << " offset " << i;
          }
        }
      }
    }
  }
}

TEST(FillUniform01, PublicEntryPointUsesBestKernel) {
  std::vector<double> a(7 * 19);
  std::vector<double> b(7 * 19);
  fill_uniform01(8, Stream::Measurement, 1000, 7, 19, a);
  detail::fill_uniform01_with(detail::PhiloxKernel::Generic, 8, Stream::Measurement, 1000, 7, 19,
                              b);
  EXPECT_EQ(a, b);
}

TEST(FillUniform01, DrawMajorIsTheTransposeOfSampleMajor) {
  const std::size_t count = 33, n = 1024 + 5;
  std::vector<double> by_sample(count * n), by_draw(count * n);
  fill_uniform01(4, Stream::Uncertainties, 3 * 1024, count, n, by_sample);
  fill_uniform01_draw_major(4, Stream::Uncertainties, 3 * 1024, count, n, by_draw);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < count; ++j) ASSERT_EQ(by_draw[j * n + i], by_sample[i * count + j]) << i << " " << j;
}

TEST(FillUniform01, EmptyRequestWritesNothing) {
  // An empty span at the front of a guarded buffer: nothing past it changes.
  std::vector<double> guarded(64, -7.0);
  const std::span<double> none(guarded.data(), 0);
  fill_uniform01(1, Stream::Sway, 0, 0, 10, none);
  fill_uniform01(1, Stream::Sway, 0, 10, 0, none);
  fill_uniform01_draw_major(1, Stream::Sway, 0, 0, 10, none);
  fill_uniform01_draw_major(1, Stream::Sway, 0, 10, 0, none);
  for (const double v : guarded) EXPECT_EQ(v, -7.0);
}

// ---------------------------------------------------------------- uniform transforms

TEST(Uniform, RangeAndResolutionAtExtremeWords) {
  EXPECT_EQ(uniform01_from_words(0, 0), 0.0);
  EXPECT_EQ(uniform01_from_words(0xffffffffu, 0xffffffffu), 1.0 - 0x1p-53);
  EXPECT_EQ(uniform01_from_words(0, 1u << 11), 0x1p-53);  // lowest used bit
  EXPECT_EQ(uniform01_from_words(0, (1u << 11) - 1), 0.0);  // discarded bits
  EXPECT_EQ(open_uniform01_from_words(0, 0), 0x1p-53);
  EXPECT_EQ(open_uniform01_from_words(0xffffffffu, 0xffffffffu), 1.0 - 0x1p-53);
}

TEST(Uniform, OpenUniformIsExactlySymmetric) {
  // Complementing the words maps k to 2^52 - 1 - k, i.e. u to 1 - u exactly.
  std::mt19937 words(3u);
  for (int i = 0; i < 10000; ++i) {
    const std::uint32_t hi = w32(words);
    const std::uint32_t lo = w32(words);
    const double u = open_uniform01_from_words(hi, lo);
    ASSERT_GT(u, 0.0);
    ASSERT_LT(u, 1.0);
    ASSERT_EQ(1.0 - u, open_uniform01_from_words(~hi, ~lo));
  }
}

TEST(Uniform, DrawsStayInHalfOpenInterval) {
  CounterStream s(42, Stream::Uncertainties, 0);
  for (int i = 0; i < 200000; ++i) {
    const double u = s.uniform01();
    ASSERT_GE(u, 0.0);
    ASSERT_LT(u, 1.0);
  }
  CounterStream t(42, Stream::Uncertainties, 1);
  for (int i = 0; i < 1000; ++i) {
    const double x = t.uniform(-3.0, 5.0);
    ASSERT_GE(x, -3.0);
    ASSERT_LT(x, 5.0);
  }
}

// ---------------------------------------------------------------- inverse normal CDF

// Reference residual Phi(x) - p in long double (64-bit significand, about
// 1e-19 relative), from erfl near the centre (where p - 1/2 is exact) and
// erfcl in the lower tail. Upper-tail p are handled by symmetry by the caller.
long double reference_residual(long double x, double p) {
  const long double s = x / std::sqrt(2.0L);
  if (p >= 0.25) return 0.5L * std::erf(s) - (static_cast<long double>(p) - 0.5L);
  return 0.5L * std::erfc(-s) - static_cast<long double>(p);
}

// Two Newton steps from the candidate in long double: the reference quantile.
long double reference_quantile_lower(double p, double start) {
  long double x = start;
  for (int i = 0; i < 2; ++i) {
    const long double density =
        std::exp(-0.5L * x * x) / std::sqrt(2.0L * std::numbers::pi_v<long double>);
    x -= reference_residual(x, p) / density;
  }
  return x;
}

std::vector<double> probability_grid() {
  std::vector<double> p;
  for (int k = 1; k <= 307; ++k) p.push_back(std::pow(10.0, -k));
  for (int k = 2; k <= 1022; k += 5) p.push_back(std::ldexp(1.0, -k));
  for (int j = 1; j < 1000; ++j) p.push_back(j / 1000.0);
  for (int k = 2; k <= 52; ++k) p.push_back(0.5 - std::ldexp(1.0, -k));
  p.push_back(1.3888e-11);  // around the r = 5 split of AS 241
  p.push_back(1.3889e-11);
  p.push_back(0.075);  // the |q| = 0.425 split
  p.push_back(0.0749999999);
  p.push_back(0.0750000001);
  return p;  // all in (0, 1/2]; the upper half is covered by symmetry below
}

TEST(InverseNormalCdf, RelativeAccuracyAgainstErfcReference) {
  // AS 241 claims about 1e-16 relative; we require 1e-14 relative in x.
  constexpr double kRelTol = 1e-14;
  for (const double p : probability_grid()) {
    const double x = inverse_normal_cdf(p);
    if (p == 0.5) {
      EXPECT_EQ(x, 0.0);
      continue;
    }
    const long double ref = reference_quantile_lower(p, x);
    const double rel = static_cast<double>(std::fabs((x - ref) / ref));
    EXPECT_LE(rel, kRelTol) << "p = " << p << " x = " << x << " ref = " << static_cast<double>(ref);
  }
}

TEST(InverseNormalCdf, ExactSymmetryAndEndpoints) {
  for (const double p : probability_grid()) {
    const double upper = 1.0 - p;  // exact for p in [1/4, 1/2]; checked below
    if (1.0 - upper != p) continue;
    EXPECT_EQ(inverse_normal_cdf(upper), -inverse_normal_cdf(p)) << "p = " << p;
  }
  EXPECT_EQ(inverse_normal_cdf(0.0), -std::numeric_limits<double>::infinity());
  EXPECT_EQ(inverse_normal_cdf(1.0), std::numeric_limits<double>::infinity());
}

TEST(InverseNormalCdf, RoundTripThroughDoubleErfc) {
  // Phi(x) = erfc(-x/sqrt2)/2 in double. The round trip's relative error in p
  // is the error of x times the condition number |x phi(x)/Phi(x)| ~ 1 + x^2,
  // plus a few ulp from erfc and from rounding -x/sqrt2.
  constexpr double kUlps = 16.0;
  for (const double p : probability_grid()) {
    const double x = inverse_normal_cdf(p);
    const double back = normal_cdf(x);
    const double tol = kUlps * kEps * (1.0 + x * x) * p;
    EXPECT_NEAR(back, p, tol) << "p = " << p << " x = " << x;
  }
}

TEST(InverseNormalCdf, MonotoneOnAFineGrid) {
  double previous = -std::numeric_limits<double>::infinity();
  for (int j = 1; j < 200000; ++j) {
    const double x = inverse_normal_cdf(j / 200000.0);
    ASSERT_GT(x, previous) << "j = " << j;
    previous = x;
  }
}

// ---------------------------------------------------------------- truncated normal

TEST(TruncatedNormal, StaysWithinBoundAndIsAntisymmetric) {
  struct Case {
    double sigma;
    double bound;
  };
  const std::array<Case, 6> cases{{{1.0, 3.0}, {2.0, 0.5}, {1e-12, 1e-12}, {1.0, 40.0},
                                    {3.0, std::numeric_limits<double>::infinity()},
                                    {1e-3, 2.5e-3}}};
  // Values whose complement 1 - u is exact (as for open_uniform01 draws).
  const std::array<double, 7> us{0x1p-53, 0x1p-34, 0.125, 0.5, 0.875, 1.0 - 0x1p-34, 1.0 - 0x1p-53};
  for (const Case& c : cases) {
    const TruncatedNormalTransform t(c.sigma, c.bound);
    for (const double u : us) {
      const double x = t(u);
      EXPECT_LE(std::fabs(x), c.bound) << "sigma " << c.sigma << " bound " << c.bound << " u " << u;
      EXPECT_TRUE(std::isfinite(x));
      EXPECT_EQ(t(1.0 - u), -x) << "sigma " << c.sigma << " u " << u;
    }
  }
}

TEST(TruncatedNormal, DegenerateCasesReturnZero) {
  EXPECT_EQ(TruncatedNormalTransform(0.0, 1.0)(0.3), 0.0);
  EXPECT_EQ(TruncatedNormalTransform(1.0, 0.0)(0.3), 0.0);
  CounterStream s(1, Stream::Uncertainties, 0);
  EXPECT_EQ(s.truncated_normal(0.0, 5.0), 0.0);
  EXPECT_EQ(s.position(), 2u);  // still consumes its two words
}

TEST(TruncatedNormal, InfiniteBoundIsScaledNormal) {
  const TruncatedNormalTransform t(2.5, std::numeric_limits<double>::infinity());
  for (const double u : {0.001, 0.2, 0.5, 0.7, 0.999}) {
    const double lower = u < 0.5 ? u : 1.0 - u;
    const double z = inverse_normal_cdf(lower);
    EXPECT_EQ(t(u), u < 0.5 ? 2.5 * z : -(2.5 * z)) << "u " << u;
  }
}

// ---------------------------------------------------------------- KS tests
//
// Statistic: D_n = sup_x |F_n(x) - F(x)| for n draws against the exact CDF F.
// Sampling distribution: for continuous F, the Dvoretzky-Kiefer-Wolfowitz
// inequality with Massart's constant (Ann. Probab. 18 (1990) 1269) gives
// P(D_n > eps) <= 2 exp(-2 n eps^2) for every n, so eps = sqrt(ln(2/a)/(2n))
// is a critical value at level a (conservative; it is also the leading term
// of the asymptotic Kolmogorov distribution). The draws live on a 2^-52 grid,
// far finer than eps ~ 1e-2, so F may be treated as continuous.
// Family-wise alpha 1e-6 for this file's KS assertions, split (Bonferroni)
// over kKsAssertions. Seeds are fixed; a failure is a one-in-a-million event.
//
// Power companions: the same check against F((x)/(1 + h)), a CDF at sup
// distance delta from F. If delta > 2 eps then D_n against it exceeds
// delta - eps > eps whenever the true D_n <= eps, i.e. with probability
// >= 1 - a. Each companion computes delta and asserts delta > 2 eps first.

constexpr double kFamilyAlpha = 1e-6;
constexpr int kKsAssertions = 6;  // uniform, normal, four truncated cases
constexpr double kKsAlpha = kFamilyAlpha / kKsAssertions;
constexpr std::size_t kKsDraws = 100000;
constexpr double kPowerScale = 0.1;  // h: 10% scale perturbation

double ks_critical_value(std::size_t n, double alpha) {
  return std::sqrt(std::log(2.0 / alpha) / (2.0 * static_cast<double>(n)));
}

double ks_statistic(std::vector<double> x, const std::function<double(double)>& cdf) {
  std::sort(x.begin(), x.end());
  const double n = static_cast<double>(x.size());
  double d = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double f = cdf(x[i]);
    d = std::max({d, static_cast<double>(i + 1) / n - f, f - static_cast<double>(i) / n});
  }
  return d;
}

// sup over a fine grid of |F(x) - F(x/(1+h))| (a lower bound of the sup).
double perturbation_distance(const std::function<double(double)>& cdf, double lo, double hi) {
  double d = 0.0;
  constexpr int kGrid = 20000;
  for (int i = 0; i <= kGrid; ++i) {
    const double x = lo + (hi - lo) * i / kGrid;
    d = std::max(d, std::fabs(cdf(x) - cdf(x / (1.0 + kPowerScale))));
  }
  return d;
}

void check_ks(const std::string& name, const std::vector<double>& draws,
              const std::function<double(double)>& cdf, double support_lo, double support_hi) {
  const double eps = ks_critical_value(draws.size(), kKsAlpha);
  const double d = ks_statistic(draws, cdf);
  EXPECT_LE(d, eps) << name << ": D_n = " << d << " exceeds critical value " << eps;
  // Power companion.
  const auto perturbed = [&](double x) { return cdf(x / (1.0 + kPowerScale)); };
  const double delta = perturbation_distance(cdf, support_lo, support_hi);
  ASSERT_GT(delta, 2.0 * eps) << name << ": perturbation too small for power >= 1 - alpha";
  const double d_wrong = ks_statistic(draws, perturbed);
  EXPECT_GT(d_wrong, eps) << name << ": KS check cannot detect a 10% scale error";
}

TEST(KolmogorovSmirnov, Uniform01) {
  CounterStream s(20240601, Stream::Uncertainties, 0);
  std::vector<double> draws(kKsDraws);
  for (double& u : draws) u = s.uniform01();
  check_ks("uniform01", draws, [](double x) { return std::clamp(x, 0.0, 1.0); }, 0.0, 1.0);
}

TEST(KolmogorovSmirnov, StandardNormal) {
  CounterStream s(20240602, Stream::Uncertainties, 0);
  std::vector<double> draws(kKsDraws);
  for (double& z : draws) z = s.standard_normal();
  // Independent CDF: std::erfc, not the inverse under test.
  check_ks("standard_normal", draws,
           [](double x) { return 0.5 * std::erfc(-x / std::numbers::sqrt2); }, -8.0, 8.0);
}

TEST(KolmogorovSmirnov, TruncatedNormal) {
  struct Case {
    double sigma;
    double bound;
  };
  // Tight (nearly uniform), moderate, the paper's 2.5-sigma style, and wide.
  constexpr std::array<Case, 4> cases{{{1.0, 0.5}, {2.0, 3.0}, {1e-3, 2.5e-3}, {1.0, 6.0}}};
  static_assert(2 + cases.size() == kKsAssertions);
  std::uint64_t index = 0;
  for (const Case& c : cases) {
    CounterStream s(20240603, Stream::Uncertainties, index++);
    std::vector<double> draws(kKsDraws);
    for (double& x : draws) x = s.truncated_normal(c.sigma, c.bound);
    const double lo = 0.5 * std::erfc(c.bound / c.sigma / std::numbers::sqrt2);
    const double mass = std::erf(c.bound / c.sigma / std::numbers::sqrt2);
    const auto cdf = [&](double x) {
      if (x <= -c.bound) return 0.0;
      if (x >= c.bound) return 1.0;
      return (0.5 * std::erfc(-x / c.sigma / std::numbers::sqrt2) - lo) / mass;
    };
    check_ks("truncated_normal sigma=" + std::to_string(c.sigma) + " bound=" +
                 std::to_string(c.bound),
             draws, cdf, -c.bound * (1.0 + kPowerScale), c.bound * (1.0 + kPowerScale));
  }
}

}  // namespace
}  // namespace insmc::mc
