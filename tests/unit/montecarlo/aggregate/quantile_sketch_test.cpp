// Tests for montecarlo/aggregate/quantile_sketch.h: exact mode against a
// full sort, the stated relative error in bucketed mode, merge == one pass
// (identical quantiles and bytes) over random splits and orders, the bucket
// collapse, zeros, and bit-exact serialisation.
#include "montecarlo/aggregate/quantile_sketch.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <vector>

#include "montecarlo/random/philox.h"

namespace insmc::mc {
namespace {

constexpr double kAlpha = QuantileSketch::kRelativeAccuracy;
// The bucket edges are evaluated with log(); a value within a few ulp of an
// edge can land in the neighbouring bucket, adding a few ulp to alpha.
constexpr double kEdgeSlack = 1e-12;
constexpr std::array<double, 11> kQs{0.0,  0.001, 0.01, 0.25,  0.5, 0.75,
                                     0.9,  0.95,  0.99, 0.999, 1.0};

// Independent reference: nearest-rank quantile of |x| by full sort.
double reference_quantile(std::vector<double> values, double q) {
  for (double& v : values) v = std::fabs(v);
  std::sort(values.begin(), values.end());
  const double n = static_cast<double>(values.size());
  auto k = static_cast<std::size_t>(std::ceil(q * n));
  k = std::clamp<std::size_t>(k, 1, values.size());
  return values[k - 1];
}

QuantileSketch one_pass(const std::vector<double>& values) {
  QuantileSketch s;
  for (const double v : values) s.add(v);
  return s;
}

std::vector<double> normal_values(std::uint64_t seed, std::size_t n, double scale) {
  CounterStream rng(seed, Stream::Bootstrap, 0);
  std::vector<double> v(n);
  for (double& x : v) x = scale * rng.standard_normal();
  return v;
}

TEST(QuantileSketch, EmptyReturnsNaN) {
  const QuantileSketch s;
  EXPECT_EQ(s.count(), 0u);
  EXPECT_TRUE(std::isnan(s.abs_quantile(0.5)));
}

TEST(QuantileSketch, ExactModeMatchesFullSort) {
  for (const std::size_t n : {1u, 2u, 3u, 20u, 200u, 4096u}) {
    const std::vector<double> values = normal_values(n, n, 2.0);
    const QuantileSketch s = one_pass(values);
    EXPECT_TRUE(s.is_exact());
    for (const double q : kQs) {
      EXPECT_EQ(s.abs_quantile(q), reference_quantile(values, q)) << "n " << n << " q " << q;
    }
  }
}

TEST(QuantileSketch, NearestRankDefinition) {
  // |x| = 1..10: p95 is the 10th smallest (ceil(9.5) = 10), p50 the 5th.
  QuantileSketch s;
  for (int i = 1; i <= 10; ++i) s.add(i % 2 ? -i : i);
  EXPECT_EQ(s.abs_quantile(0.95), 10.0);
  EXPECT_EQ(s.abs_quantile(0.5), 5.0);
  EXPECT_EQ(s.abs_quantile(0.0), 1.0);
  EXPECT_EQ(s.abs_quantile(0.1), 1.0);
  EXPECT_EQ(s.abs_quantile(0.11), 2.0);
}

TEST(QuantileSketch, SwitchesToBucketsAfterCapacity) {
  const std::vector<double> values = normal_values(7, QuantileSketch::kExactCapacity + 1, 1.0);
  QuantileSketch s;
  for (std::size_t i = 0; i < QuantileSketch::kExactCapacity; ++i) s.add(values[i]);
  EXPECT_TRUE(s.is_exact());
  s.add(values.back());
  EXPECT_FALSE(s.is_exact());
  EXPECT_GT(s.bucket_count(), 0u);
}

TEST(QuantileSketch, BucketedModeWithinStatedRelativeError) {
  struct Case {
    const char* name;
    std::vector<double> values;
  };
  std::vector<Case> cases;
  cases.push_back({"normal sigma 3e-6", normal_values(11, 60000, 3e-6)});
  {
    // Log-normal over ~6 decades (inside the 4.8e8 uncollapsed range).
    CounterStream rng(12, Stream::Bootstrap, 0);
    std::vector<double> v(60000);
    for (double& x : v) x = std::exp(1.5 * rng.standard_normal());
    cases.push_back({"lognormal", v});
  }
  {
    // Uniform, some exact duplicates, and values on bucket edges gamma^i.
    CounterStream rng(13, Stream::Bootstrap, 0);
    const double gamma = (1 + kAlpha) / (1 - kAlpha);
    std::vector<double> v(20000);
    for (std::size_t i = 0; i < v.size(); ++i) {
      v[i] = i % 3 == 0 ? std::pow(gamma, static_cast<double>(i % 500)) : rng.uniform(-50.0, 50.0);
    }
    cases.push_back({"uniform with edges", v});
  }
  for (const Case& c : cases) {
    const QuantileSketch s = one_pass(c.values);
    ASSERT_FALSE(s.is_exact());
    for (const double q : kQs) {
      const double exact = reference_quantile(c.values, q);
      const double got = s.abs_quantile(q);
      EXPECT_LE(std::fabs(got - exact), (kAlpha + kEdgeSlack) * exact)
          << c.name << " q " << q << " exact " << exact << " sketch " << got;
    }
  }
}

TEST(QuantileSketch, ZerosAreExact) {
  std::vector<double> values(10000, 0.0);
  for (std::size_t i = 0; i < 1000; ++i) values[i] = -0.0;
  for (std::size_t i = 9000; i < values.size(); ++i) values[i] = static_cast<double>(i);
  const QuantileSketch s = one_pass(values);
  EXPECT_EQ(s.abs_quantile(0.5), 0.0);
  EXPECT_EQ(s.abs_quantile(0.9), 0.0);  // rank 9000 is the last zero
  EXPECT_NEAR(s.abs_quantile(0.95), 9499.0, kAlpha * 9499.0);
  EXPECT_EQ(s.abs_quantile(1.0), 9999.0);  // clamped to the exact max
}

TEST(QuantileSketch, CollapseBoundsMemoryAndKeepsUpperQuantiles) {
  // |x| spans 1e-14 .. 1e3, wider than gamma^(kMaxBuckets-1) ~ 4.8e8, so
  // the lowest buckets are collapsed. Quantiles above the threshold keep
  // the stated error; below it they are bounded above by the threshold.
  CounterStream rng(14, Stream::Bootstrap, 0);
  std::vector<double> values(30000);
  for (double& x : values) x = std::pow(10.0, rng.uniform(-14.0, 3.0));
  const QuantileSketch s = one_pass(values);
  EXPECT_EQ(s.bucket_count(), QuantileSketch::kMaxBuckets);
  const double gamma = (1 + kAlpha) / (1 - kAlpha);
  const double max_abs = reference_quantile(values, 1.0);
  const double threshold = max_abs / std::pow(gamma, QuantileSketch::kMaxBuckets - 1.0);
  for (const double q : kQs) {
    const double exact = reference_quantile(values, q);
    const double got = s.abs_quantile(q);
    if (exact > threshold * gamma) {
      EXPECT_LE(std::fabs(got - exact), (kAlpha + kEdgeSlack) * exact) << "q " << q;
    } else {
      EXPECT_LE(got, threshold * gamma) << "q " << q;
    }
  }
}

// Splits at random cut points, builds each part, merges left to right.
QuantileSketch merged_in_parts(const std::vector<double>& values, CounterStream& rng,
                               bool reverse_order) {
  const auto n_parts = 1 + static_cast<std::size_t>(rng.uniform01() * 10);
  std::vector<std::size_t> cuts{0, values.size()};
  for (std::size_t i = 1; i < n_parts; ++i) {
    cuts.push_back(static_cast<std::size_t>(rng.uniform01() * static_cast<double>(values.size())));
  }
  std::sort(cuts.begin(), cuts.end());
  std::vector<QuantileSketch> parts;
  for (std::size_t p = 0; p + 1 < cuts.size(); ++p) {
    QuantileSketch part;
    for (std::size_t i = cuts[p]; i < cuts[p + 1]; ++i) part.add(values[i]);
    parts.push_back(part);
  }
  if (reverse_order) std::reverse(parts.begin(), parts.end());
  QuantileSketch total;
  for (const auto& part : parts) total.merge(part);
  return total;
}

TEST(QuantileSketchMerge, EqualsOnePassExactly) {
  // Sizes on both sides of the exact capacity, so parts mix exact and
  // bucketed modes; values over a range wide enough to collapse buckets.
  CounterStream rng(15, Stream::Bootstrap, 0);
  for (int trial = 0; trial < 40; ++trial) {
    const auto n = 1 + static_cast<std::size_t>(rng.uniform01() * 12000);
    std::vector<double> values(n);
    for (double& x : values) {
      const double u = rng.uniform01();
      x = u < 0.05 ? 0.0 : (u < 0.5 ? -1.0 : 1.0) * std::pow(10.0, rng.uniform(-12.0, 2.0));
    }
    const QuantileSketch a = one_pass(values);
    const std::string bytes = a.serialize();
    for (const bool reverse : {false, true}) {
      const QuantileSketch b = merged_in_parts(values, rng, reverse);
      ASSERT_EQ(b.count(), a.count());
      ASSERT_EQ(b.is_exact(), a.is_exact()) << "trial " << trial;
      ASSERT_EQ(b.serialize(), bytes) << "trial " << trial << " n " << n << " reverse " << reverse;
      for (const double q : kQs) {
        ASSERT_EQ(b.abs_quantile(q), a.abs_quantile(q)) << "trial " << trial << " q " << q;
      }
    }
  }
}

TEST(QuantileSketchMerge, EmptyIsAnExactIdentity) {
  for (const std::size_t n : {10u, 5000u}) {
    const QuantileSketch s = one_pass(normal_values(16, n, 1.0));
    QuantileSketch left;
    left.merge(s);
    QuantileSketch right = s;
    right.merge(QuantileSketch{});
    EXPECT_EQ(left.serialize(), s.serialize());
    EXPECT_EQ(right.serialize(), s.serialize());
  }
}

TEST(QuantileSketchSerialize, RoundTripIsBitExact) {
  for (const std::size_t n : {0u, 1u, 100u, 4096u, 4097u, 50000u}) {
    const QuantileSketch s = one_pass(normal_values(17 + n, n, 1e-3));
    const std::string bytes = s.serialize();
    const QuantileSketch back = QuantileSketch::deserialize(bytes);
    EXPECT_EQ(back.serialize(), bytes) << "n " << n;
    EXPECT_EQ(back.count(), s.count());
    EXPECT_EQ(back.is_exact(), s.is_exact());
    for (const double q : kQs) {
      if (n == 0) continue;
      EXPECT_EQ(back.abs_quantile(q), s.abs_quantile(q)) << "n " << n << " q " << q;
    }
  }
}

TEST(QuantileSketchSerialize, MalformedInputThrows) {
  for (const std::size_t n : {10u, 5000u}) {
    const std::string good = one_pass(normal_values(18, n, 1.0)).serialize();
    EXPECT_THROW(QuantileSketch::deserialize(good.substr(0, good.size() - 3)), std::runtime_error);
    EXPECT_THROW(QuantileSketch::deserialize(good + "abc"), std::runtime_error);
    std::string bad_tag = good;
    bad_tag[1] = 'X';
    EXPECT_THROW(QuantileSketch::deserialize(bad_tag), std::runtime_error);
    std::string bad_mode = good;
    bad_mode[4] = 7;
    EXPECT_THROW(QuantileSketch::deserialize(bad_mode), std::runtime_error);
  }
  // Bucketed with counts not summing to n.
  std::string bad_count = one_pass(normal_values(19, 5000, 1.0)).serialize();
  bad_count[8] = static_cast<char>(bad_count[8] + 1);  // n's low byte
  EXPECT_THROW(QuantileSketch::deserialize(bad_count), std::runtime_error);
}

}  // namespace
}  // namespace insmc::mc
