// Tests for montecarlo/study/aggregate/exact_sum.h: the same adds in any grouping
// and order give the same bytes; value() against sums that are exact in
// long double and against known cancellations; negative values; truncation
// below 2^-128; the serialised layout and its round trip.
#include "montecarlo/study/aggregate/exact_sum.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>
#include <vector>

#include "montecarlo/study/random/philox.h"
#include "tests/unit/montecarlo/study/aggregate/permutation.h"

namespace insmc::mc {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();
constexpr std::size_t kStateBytes = 48;  // six 64-bit limbs

std::string bytes_of(const ExactSum& s) {
  std::string out;
  s.append_to(out);
  return out;
}

ExactSum sum_of(const std::vector<double>& values) {
  ExactSum s;
  for (const double v : values) s.add(v);
  return s;
}

// Doubles of both signs over 2^-60 .. 2^60 with full 53-bit mantissas: every
// add lands on different limbs and carries across them.
std::vector<double> wide_values(std::uint64_t seed, std::size_t n) {
  CounterStream rng(seed, Stream::Bootstrap, 0);
  std::vector<double> v(n);
  for (double& x : v) {
    const double mag = std::ldexp(1.0 + rng.uniform01(), static_cast<int>(rng.uniform(-60.0, 61.0)));
    x = rng.uniform01() < 0.5 ? -mag : mag;
  }
  return v;
}

using testing::permutation;

// ---------------------------------------------------------------- exactness

TEST(ExactSum, AnyGroupingAndOrderGivesTheSameBytes) {
  CounterStream rng(2, Stream::Bootstrap, 0);
  for (int trial = 0; trial < 50; ++trial) {
    const std::vector<double> values = wide_values(100 + static_cast<std::uint64_t>(trial), 2000);
    const std::string expected = bytes_of(sum_of(values));

    // Reversed and shuffled add order.
    ExactSum reversed;
    for (auto it = values.rbegin(); it != values.rend(); ++it) reversed.add(*it);
    ASSERT_EQ(bytes_of(reversed), expected) << "trial " << trial;
    ExactSum shuffled;
    for (const std::size_t i : permutation(values.size(), rng)) shuffled.add(values[i]);
    ASSERT_EQ(bytes_of(shuffled), expected) << "trial " << trial;

    // Random parts (each value to a random part), merged in random order.
    const auto n_parts = 1 + static_cast<std::size_t>(rng.uniform01() * 12);
    std::vector<ExactSum> parts(n_parts);
    for (const double v : values) parts[static_cast<std::size_t>(rng.uniform01() * static_cast<double>(n_parts))].add(v);
    ExactSum merged;
    for (const std::size_t p : permutation(n_parts, rng)) merged.merge(parts[p]);
    ASSERT_EQ(bytes_of(merged), expected) << "trial " << trial;
    ASSERT_TRUE(merged == sum_of(values));

    // A merge tree: ((p0 + p1) + (p2 + p3)) ... pairwise.
    while (parts.size() > 1) {
      std::vector<ExactSum> next;
      for (std::size_t i = 0; i + 1 < parts.size(); i += 2) {
        next.push_back(parts[i + 1]);
        next.back().merge(parts[i]);
      }
      if (parts.size() % 2 == 1) next.push_back(parts.back());
      parts = next;
    }
    ASSERT_EQ(bytes_of(parts.front()), expected) << "trial " << trial;
  }
}

TEST(ExactSum, EmptyIsTheIdentityAndAllZeroBytes) {
  const ExactSum empty;
  EXPECT_EQ(empty.value(), 0.0);
  EXPECT_EQ(bytes_of(empty), std::string(kStateBytes, '\0'));
  const ExactSum s = sum_of({0.1, -7.25, 3e10});
  ExactSum left;
  left.merge(s);
  ExactSum right = s;
  right.merge(ExactSum{});
  EXPECT_EQ(bytes_of(left), bytes_of(s));
  EXPECT_EQ(bytes_of(right), bytes_of(s));
  // Adding zeros (of either sign) changes nothing.
  ExactSum z = s;
  z.add(0.0);
  z.add(-0.0);
  EXPECT_EQ(bytes_of(z), bytes_of(s));
}

// ---------------------------------------------------------------- value()

TEST(ExactSum, ValueIsCorrectlyRoundedWhenTheSumFitsInLongDouble) {
  // Values k 2^-40 with |k| < 2^50 (|x| < 2^10), 8192 of them: every
  // partial sum is a multiple of 2^-40 below 2^23 in magnitude, i.e. an
  // integer below 2^63 times 2^-40, so the long double (64-bit significand)
  // running sum is exact and its rounding to double is the correctly
  // rounded sum. value() rounds once from an exact long double here too.
  static_assert(std::numeric_limits<long double>::digits >= 64);
  CounterStream rng(3, Stream::Bootstrap, 0);
  for (int trial = 0; trial < 20; ++trial) {
    const double sign_bias = trial % 2 ? 0.5 : 0.8;  // mixed signs, or mostly positive
    ExactSum s;
    long double exact = 0.0L;
    for (int i = 0; i < 8192; ++i) {
      const double k = std::floor(rng.uniform01() * 0x1p50);
      const double x = std::ldexp(rng.uniform01() < sign_bias ? k : -k, -40);
      s.add(x);
      exact += x;
    }
    EXPECT_EQ(s.value(), static_cast<double>(exact)) << "trial " << trial;
  }
}

TEST(ExactSum, ValueMatchesLongDoubleForPositiveWideSums) {
  // Positive values over 2^-60..2^60 (condition number 1). The long double
  // reference has relative error <= n 2^-64 (recursive summation, Higham
  // 4.2); value() is within a few ulp (its long double fold and the final
  // rounding). n = 1000 gives 1000 * 2^-64 = 0.5 ulp of double.
  constexpr std::size_t kN = 1000;
  constexpr double kValueTol = 4 * kEps;  // relative: reference error + value()'s roundings
  for (std::uint64_t seed = 10; seed < 30; ++seed) {
    std::vector<double> values = wide_values(seed, kN);
    for (double& v : values) v = std::fabs(v);
    long double reference = 0.0L;
    for (const double v : values) reference += v;
    const double got = sum_of(values).value();
    EXPECT_NEAR(got, static_cast<double>(reference), kValueTol * static_cast<double>(reference))
        << "seed " << seed;
  }
}

TEST(ExactSum, KnownSums) {
  struct Case {
    const char* name;
    std::vector<double> values;
    double expected;
  };
  const std::vector<Case> cases{
      // Catastrophic cancellation that naive double summation gets wrong.
      {"2^200 + 1 - 2^200", {0x1p200, 1.0, -0x1p200}, 1.0},
      {"1e60 + 3.14 - 1e60", {1e60, 3.14, -1e60}, 3.14},
      {"1 + 2^-100 - 1", {1.0, 0x1p-100, -1.0}, 0x1p-100},
      // Ten copies of fl(0.1) sum to 1 + 2^-54 + ..., which rounds to 1.
      {"10 x 0.1", std::vector<double>(10, 0.1), 1.0},
      {"negative total", {-3.5, 1.25, -0.75}, -3.0},
      {"largest allowed magnitude", {0x1.fffffffffffffp249, -0x1.fffffffffffffp249, -0x1p249}, -0x1p249},
  };
  for (const Case& c : cases) {
    EXPECT_EQ(sum_of(c.values).value(), c.expected) << c.name;
  }
}

TEST(ExactSum, CancellationToExactZero) {
  // x_i then -x_i in a shuffled order: the register returns to all zero
  // bits (truncation toward zero is symmetric in sign).
  CounterStream rng(4, Stream::Bootstrap, 0);
  const std::vector<double> values = wide_values(5, 3000);
  std::vector<double> both = values;
  for (const double v : values) both.push_back(-v);
  std::vector<double> shuffled;
  for (const std::size_t i : permutation(both.size(), rng)) shuffled.push_back(both[i]);
  const ExactSum s = sum_of(shuffled);
  EXPECT_EQ(s.value(), 0.0);
  EXPECT_FALSE(std::signbit(s.value()));
  EXPECT_EQ(bytes_of(s), std::string(kStateBytes, '\0'));
}

TEST(ExactSum, ValuesBelowTheResolutionAreTruncatedTowardZero) {
  constexpr double kResolution = 0x1p-128;
  struct Case {
    const char* name;
    double x;
    double kept;  // the value actually added
  };
  const std::vector<Case> cases{
      {"2^-128", kResolution, kResolution},
      {"-2^-128", -kResolution, -kResolution},
      {"2^-129", 0x1p-129, 0.0},
      {"-2^-129", -0x1p-129, 0.0},
      {"1.5 * 2^-128", 1.5 * kResolution, kResolution},
      {"-1.5 * 2^-128", -1.5 * kResolution, -kResolution},
      {"3.75 * 2^-128", 3.75 * kResolution, 3 * kResolution},
      {"denorm_min", std::numeric_limits<double>::denorm_min(), 0.0},
      {"1 + 2^-52 keeps every bit", 1.0 + 0x1p-52, 1.0 + 0x1p-52},
      {"2^-100 + 2^-140 drops the low bit", 0x1p-100 + 0x1p-140, 0x1p-100},
  };
  for (const Case& c : cases) {
    ExactSum s;
    s.add(c.x);
    EXPECT_EQ(s.value(), c.kept) << c.name;
    // Deterministic: the same as adding the kept value.
    ExactSum t;
    t.add(c.kept);
    EXPECT_EQ(bytes_of(s), bytes_of(t)) << c.name;
  }
  // A million values below the resolution still sum to exactly zero.
  ExactSum tiny;
  for (int i = 0; i < 1'000'000; ++i) tiny.add(0x1p-129);
  EXPECT_EQ(bytes_of(tiny), std::string(kStateBytes, '\0'));
}

TEST(ExactSum, NegativeTotalsAndMixedSigns) {
  CounterStream rng(6, Stream::Bootstrap, 0);
  for (int trial = 0; trial < 20; ++trial) {
    // Integers (exact everywhere): the exact total is known in int64.
    ExactSum s;
    std::int64_t total = 0;
    for (int i = 0; i < 5000; ++i) {
      const auto k = static_cast<std::int64_t>(std::floor(rng.uniform(-1e9, 0.5e9)));
      s.add(static_cast<double>(k));
      total += k;
    }
    ASSERT_LT(total, 0);
    EXPECT_EQ(s.value(), static_cast<double>(total)) << "trial " << trial;
  }
}

// ---------------------------------------------------------------- serialisation

TEST(ExactSum, SerializeRoundTripAndLayout) {
  for (const std::vector<double>& values :
       {std::vector<double>{}, std::vector<double>{1.0}, std::vector<double>{-1.0},
        wide_values(7, 500), std::vector<double>{-0x1p249, -0x1p249}}) {
    const ExactSum s = sum_of(values);
    std::string bytes = "prefix";
    s.append_to(bytes);
    EXPECT_EQ(bytes.size(), 6 + kStateBytes);
    std::size_t pos = 6;
    const ExactSum back = ExactSum::read_from(bytes, pos);
    EXPECT_EQ(pos, bytes.size());
    EXPECT_TRUE(back == s);
    EXPECT_EQ(bytes_of(back), bytes_of(s));
    EXPECT_EQ(back.value(), s.value());
  }
  // Little-endian limbs, 128 fraction bits: 1.0 is bit 128 (limb 2, byte 16).
  const std::string one = bytes_of(sum_of({1.0}));
  for (std::size_t i = 0; i < kStateBytes; ++i) {
    EXPECT_EQ(static_cast<unsigned char>(one[i]), i == 16 ? 1u : 0u) << "byte " << i;
  }
  // -1 in two's complement: all ones above bit 128, zeros below.
  const std::string minus_one = bytes_of(sum_of({-1.0}));
  for (std::size_t i = 0; i < kStateBytes; ++i) {
    EXPECT_EQ(static_cast<unsigned char>(minus_one[i]), i < 16 ? 0u : 0xFFu) << "byte " << i;
  }
}

TEST(ExactSum, TruncatedStateThrows) {
  const std::string bytes = bytes_of(sum_of({2.5}));
  for (const std::size_t keep : {std::size_t{0}, std::size_t{1}, kStateBytes - 1}) {
    std::size_t pos = 0;
    EXPECT_THROW(ExactSum::read_from(std::string_view(bytes).substr(0, keep), pos), std::runtime_error)
        << "keep " << keep;
  }
  std::size_t past_end = bytes.size() + 1;
  EXPECT_THROW(ExactSum::read_from(bytes, past_end), std::runtime_error);
}

}  // namespace
}  // namespace insmc::mc
