// Tests for montecarlo/study/aggregate/order_statistics.h and
// horizontal_accuracy.h: the rank interval against its definition (brute
// force over Boost.Math's binomial cdf), order statistics of small known
// sets, the coverage of the quantile intervals on Rayleigh data (a
// statistical check with binomial acceptance bounds and a power companion),
// and CEP50, CEP95 and 2DRMS of a known 2-D Gaussian inside their intervals.
#include "montecarlo/study/aggregate/order_statistics.h"

#include <gtest/gtest.h>

#include <boost/math/distributions/binomial.hpp>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <limits>
#include <vector>

#include "montecarlo/study/aggregate/horizontal_accuracy.h"
#include "montecarlo/study/aggregate/output_stats.h"
#include "montecarlo/study/random/philox.h"
#include "tests/unit/montecarlo/study/aggregate/binomial_acceptance.h"

namespace insmc::mc {
namespace {

using testing::Acceptance, testing::acceptance_probability, testing::binomial_acceptance;

// P(B <= k) for B ~ Bin(n, p); 0 for k < 0.
double cdf(std::uint64_t n, double p, std::int64_t k) {
  if (k < 0) return 0.0;
  const boost::math::binomial_distribution<double> b(static_cast<double>(n), p);
  return boost::math::cdf(b, static_cast<double>(k));
}

// The exact coverage of [X_(lo), X_(hi)] for the p-quantile of continuous
// data: P(lo <= B <= hi - 1), B ~ Bin(n, p) (rank 0 and n + 1 unbounded).
double exact_coverage(std::uint64_t n, double p, RankInterval r) {
  return cdf(n, p, static_cast<std::int64_t>(r.hi) - 1) - cdf(n, p, static_cast<std::int64_t>(r.lo) - 1);
}

// ---------------------------------------------------------------- ranks

TEST(QuantileRanks, AreTheWidestTailsWithinHalfAlphaEach) {
  // For every n up to 60 and several p and confidences: P(B <= lo - 1) <= a/2
  // and lo + 1 would break it; P(B >= hi) <= a/2 and hi - 1 would break it.
  for (std::uint64_t n = 1; n <= 60; ++n) {
    for (const double p : {0.05, 0.5, 0.9, 0.95}) {
      for (const double conf : {0.5, 0.9, 0.95, 0.99}) {
        const double half = (1 - conf) / 2;
        const RankInterval r = quantile_rank_interval(n, p, conf);
        const auto lo = static_cast<std::int64_t>(r.lo), hi = static_cast<std::int64_t>(r.hi);
        ASSERT_LE(r.lo, nearest_rank(n, p));
        ASSERT_GE(r.hi, nearest_rank(n, p));
        EXPECT_LE(cdf(n, p, lo - 1), half) << n << " " << p << " " << conf;
        if (r.lo < n) {
          EXPECT_GT(cdf(n, p, lo), half) << n << " " << p << " " << conf;
        }
        EXPECT_LE(1 - cdf(n, p, hi - 1), half + 1e-15) << n << " " << p << " " << conf;
        if (r.hi > 1) {
          EXPECT_GT(1 - cdf(n, p, hi - 2), half) << n << " " << p << " " << conf;
        }
        EXPECT_GE(exact_coverage(n, p, r), conf - 1e-12) << n << " " << p << " " << conf;
      }
    }
  }
}

TEST(QuantileRanks, LargeSampleIsNearTheNormalApproximation) {
  // n = 1e5, p = 0.5: the ranks are n p -+ 1.96 sqrt(n p (1 - p)) to within
  // a couple of ranks (the binomial is close to normal there).
  const RankInterval r = quantile_rank_interval(100000, 0.5, 0.95);
  const double half = 1.959964 * std::sqrt(100000 * 0.25);
  EXPECT_NEAR(static_cast<double>(r.lo), 50000 - half, 2.0);
  EXPECT_NEAR(static_cast<double>(r.hi), 50000 + half + 1, 2.0);
}

TEST(QuantileEstimate, ReadsTheOrderStatistics) {
  // 1..20 shuffled: X_(k) = k. p = 0.5: k = 10; 95% ranks 6 and 15
  // (P(B <= 5) = 0.0207, P(B >= 15) = 0.0207 for Bin(20, 0.5)).
  std::vector<float> v = {13, 2, 20, 7, 1, 16, 9, 4, 18, 11, 5, 14, 3, 19, 8, 12, 6, 17, 10, 15};
  const QuantileEstimate q = quantile_with_interval(v, 0.5, 0.95, 0.0);
  EXPECT_EQ(q.value, 10.0);
  EXPECT_EQ(q.lo, 6.0);
  EXPECT_EQ(q.hi, 15.0);
  // Three values, the 95th percentile at 95%: no rank is low or high enough.
  std::vector<float> three = {3, 1, 2};
  const QuantileEstimate t = quantile_with_interval(three, 0.95, 0.95, -7.0);
  EXPECT_EQ(t.value, 3.0);
  EXPECT_EQ(t.lo, 2.0);  // P(B <= 1) = 0.00725 for Bin(3, 0.95)
  EXPECT_EQ(t.hi, std::numeric_limits<double>::infinity());
  std::vector<float> one = {4};
  EXPECT_EQ(quantile_with_interval(one, 0.5, 0.95, -7.0).lo, -7.0);  // rank 0: the support's lower end
  std::vector<float> none;
  EXPECT_TRUE(std::isnan(quantile_with_interval(none, 0.5, 0.95, 0.0).value));
}

// ---------------------------------------------------------------- coverage
//
// Statistic: the number X of repetitions (out of kReps) whose 95% interval
// for the p-quantile of Rayleigh data (the radial error of a 2-D Gaussian,
// sigma 1: xi_p = sqrt(-2 ln(1 - p))) contains xi_p. Each repetition draws
// kSamplesPerRep values from its own counter stream (fixed seeds). The
// order-statistic interval's exact coverage c(n, p) = P(lo <= B <= hi - 1)
// is known, so X ~ Binomial(kReps, c). Acceptance region with P(X < lo) and
// P(X > hi) <= a/2 each, a = kFamilyAlpha / kAssertions (Bonferroni over the
// two coverage assertions): a correct interval fails with probability
// <= 1e-6. Power companion: the 80% ranks used as if they were 95% have
// coverage c80 < c, and the same check must reject them; its power at c80
// is computed and required to be >= 0.999.

constexpr double kFamilyAlpha = 1e-6;
constexpr int kAssertions = 2;  // p = 0.5 and p = 0.95
constexpr int kReps = 2000;
constexpr std::uint64_t kSamplesPerRep = 200;
constexpr double kConfidence = 0.95;

double rayleigh_quantile(double p, double sigma) { return sigma * std::sqrt(-2 * std::log(1 - p)); }

// Radial errors r = sqrt(N² + E²) of n draws of a 2-D Gaussian (sigma per axis).
std::vector<float> rayleigh_values(std::uint64_t seed, std::uint64_t rep, std::uint64_t n, double sigma) {
  CounterStream rng(seed, Stream::Bootstrap, rep);
  std::vector<float> v(n);
  for (float& r : v) {
    const double north = sigma * rng.standard_normal(), east = sigma * rng.standard_normal();
    r = static_cast<float>(std::sqrt(north * north + east * east));
  }
  return v;
}

// Repetitions whose interval (ranks at `ranks_confidence`) contains xi_p.
int covered_count(double p, double ranks_confidence, std::uint64_t seed) {
  const double truth = rayleigh_quantile(p, 1.0);
  int covered = 0;
  for (int rep = 0; rep < kReps; ++rep) {
    std::vector<float> v = rayleigh_values(seed, static_cast<std::uint64_t>(rep), kSamplesPerRep, 1.0);
    const QuantileEstimate q = quantile_with_interval(v, p, ranks_confidence, 0.0);
    if (q.lo <= truth && truth <= q.hi) ++covered;
  }
  std::cout << "p = " << p << ": covered " << covered << " of " << kReps << "\n";
  return covered;
}

Acceptance acceptance_for(double p) {
  const double c = exact_coverage(kSamplesPerRep, p, quantile_rank_interval(kSamplesPerRep, p, kConfidence));
  std::cout << "exact coverage " << c << "\n";
  return binomial_acceptance(kReps, c, kFamilyAlpha / kAssertions);
}

TEST(QuantileCoverage, MedianOfRayleigh) {
  const Acceptance a = acceptance_for(0.5);
  const int x = covered_count(0.5, kConfidence, 601);
  EXPECT_GE(x, a.lo);
  EXPECT_LE(x, a.hi);
}

TEST(QuantileCoverage, NinetyFifthPercentileOfRayleigh) {
  const Acceptance a = acceptance_for(0.95);
  const int x = covered_count(0.95, kConfidence, 602);
  EXPECT_GE(x, a.lo);
  EXPECT_LE(x, a.hi);
}

TEST(QuantileCoverage, PowerTooNarrowRanksFail) {
  const Acceptance a = acceptance_for(0.5);
  const double c80 = exact_coverage(kSamplesPerRep, 0.5, quantile_rank_interval(kSamplesPerRep, 0.5, 0.80));
  ASSERT_GE(1.0 - acceptance_probability(a, kReps, c80), 0.999);
  const int x = covered_count(0.5, 0.80, 603);
  EXPECT_LT(x, a.lo) << "the coverage check cannot tell 80% ranks from 95% ones";
}

// ---------------------------------------------------------------- a known 2-D Gaussian
//
// 100,000 draws of a 2-D Gaussian with sigma = 3 km per axis: CEP50 =
// sigma sqrt(2 ln 2), CEP95 = sigma sqrt(2 ln 20), 2DRMS = 2 sqrt(2) sigma,
// each inside its interval at confidence 1 - 1e-6 (so a correct interval
// misses with probability <= 3e-6 for this fixed seed's draw).

TEST(HorizontalAccuracy, KnownGaussianMetricsLieInTheirIntervals) {
  constexpr double kSigma = 3000.0, kConf = 1 - 1e-6;
  constexpr std::uint64_t kN = 100000;
  const std::vector<float> r = rayleigh_values(604, 0, kN, kSigma);
  OutputStats stats(0.0, kSigma);
  std::vector<double> block;
  for (std::size_t i = 0; i < r.size(); i += 1024) {
    block.assign(r.begin() + static_cast<std::ptrdiff_t>(i),
                 r.begin() + static_cast<std::ptrdiff_t>(std::min<std::size_t>(i + 1024, r.size())));
    stats.add_block(block.data(), block.size());
  }
  const HorizontalAccuracy a = horizontal_accuracy(stats.summarize(kConf), r, 84 * 60.0, kConf);
  EXPECT_EQ(a.quantile_samples, kN);
  const double cep50 = kSigma * std::sqrt(2 * std::log(2.0)), cep95 = kSigma * std::sqrt(2 * std::log(20.0));
  const double drms2 = 2 * std::sqrt(2.0) * kSigma;
  EXPECT_LE(a.cep50_m.lo, cep50);
  EXPECT_GE(a.cep50_m.hi, cep50);
  EXPECT_LE(a.cep95_m.lo, cep95);
  EXPECT_GE(a.cep95_m.hi, cep95);
  EXPECT_LE(a.drms2_m.lo, drms2);
  EXPECT_GE(a.drms2_m.hi, drms2);
  // The rate is CEP50 / t, interval and all.
  EXPECT_DOUBLE_EQ(a.radial_rate_mps.value, a.cep50_m.value / (84 * 60.0));
  EXPECT_DOUBLE_EQ(a.radial_rate_mps.hi, a.cep50_m.hi / (84 * 60.0));
  std::cout << "CEP50 " << a.cep50_m.value << " [" << a.cep50_m.lo << ", " << a.cep50_m.hi << "] vs " << cep50
            << "\n";
}

TEST(HorizontalAccuracy, RateIsUndefinedAtTimeZero) {
  const HorizontalAccuracy a = horizontal_accuracy(OutputSummary{}, {1.0f, 2.0f, 3.0f}, 0.0, 0.95);
  EXPECT_TRUE(std::isnan(a.radial_rate_mps.value));
  EXPECT_EQ(a.cep50_m.value, 2.0);
}

}  // namespace
}  // namespace insmc::mc
