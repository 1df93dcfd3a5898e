// Tests for montecarlo/aggregate/moments.h: formulas against independent
// two-pass references, merge == one pass over random splits, bit-exact
// serialisation, the chi-square interval against textbook quantiles, and the
// coverage of the 95% RMS intervals (a statistical check with a binomial
// bound and power companions).
#include "montecarlo/aggregate/moments.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <boost/math/distributions/binomial.hpp>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <vector>

#include "montecarlo/random/philox.h"

namespace insmc::mc {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

ScalarMoments one_pass(const std::vector<double>& values) {
  ScalarMoments m;
  for (const double v : values) m.add(v);
  return m;
}

// Splits `values` at random cut points into parts, aggregates each part, and
// merges the parts left to right (the engine's fixed order).
ScalarMoments merged_in_parts(const std::vector<double>& values, CounterStream& rng) {
  const auto n_parts = 1 + static_cast<std::size_t>(rng.uniform01() * 8);
  std::vector<std::size_t> cuts{0, values.size()};
  for (std::size_t i = 1; i < n_parts; ++i) {
    cuts.push_back(static_cast<std::size_t>(rng.uniform01() * static_cast<double>(values.size())));
  }
  std::sort(cuts.begin(), cuts.end());
  ScalarMoments total;
  for (std::size_t p = 0; p + 1 < cuts.size(); ++p) {
    ScalarMoments part;
    for (std::size_t i = cuts[p]; i < cuts[p + 1]; ++i) part.add(values[i]);
    total.merge(part);
  }
  return total;
}

// ---------------------------------------------------------------- formulas

TEST(ScalarMoments, MatchesTwoPassFormulas) {
  // Independent reference: two-pass mean and variance, direct power sums.
  const std::vector<double> values{1.5, -2.25, 3.0, 0.0, 7.75, -1.0, 2.5};
  const double n = static_cast<double>(values.size());
  const double mean = std::accumulate(values.begin(), values.end(), 0.0) / n;
  double ss = 0.0, s2 = 0.0;
  for (const double v : values) {
    ss += (v - mean) * (v - mean);
    s2 += v * v;
  }
  const ScalarMoments m = one_pass(values);
  constexpr double kTol = 16 * kEps;  // a few roundings on O(1) numbers
  EXPECT_EQ(m.count(), values.size());
  EXPECT_NEAR(m.mean(), mean, kTol * 8);
  EXPECT_NEAR(m.stddev(), std::sqrt(ss / (n - 1)), kTol * 8);
  EXPECT_NEAR(m.rms(), std::sqrt(s2 / n), kTol * 8);
  EXPECT_EQ(m.min(), -2.25);
  EXPECT_EQ(m.max(), 7.75);
  EXPECT_EQ(m.sum_squares(), s2);  // dyadic values: exact
}

TEST(ScalarMoments, EmptyAndSingleValue) {
  ScalarMoments m;
  EXPECT_EQ(m.count(), 0u);
  EXPECT_TRUE(std::isnan(m.mean()));
  EXPECT_TRUE(std::isnan(m.rms()));
  EXPECT_TRUE(std::isnan(m.min()));
  EXPECT_TRUE(std::isnan(m.max()));
  m.add(-3.0);
  EXPECT_EQ(m.mean(), -3.0);
  EXPECT_EQ(m.rms(), 3.0);
  EXPECT_EQ(m.central_m2(), 0.0);
  EXPECT_TRUE(std::isnan(m.stddev()));
  const RmsInterval ci = m.rms_interval(0.95);
  EXPECT_TRUE(std::isnan(ci.lo) && std::isnan(ci.hi));
}

TEST(ScalarMoments, DeltaIntervalMatchesHandFormula) {
  // m2 = 19/5, m4 = 115/5, Var(RMS^2) = (m4 - m2^2)/n; z_0.975 from tables.
  const ScalarMoments m = one_pass({1.0, -1.0, 2.0, -2.0, 3.0});
  constexpr double kZ975 = 1.959963984540054;
  const double m2 = 3.8, m4 = 23.0;
  const double half = kZ975 * std::sqrt((m4 - m2 * m2) / 5.0);
  const RmsInterval ci = m.rms_interval(0.95, IntervalMethod::DeltaFourthMoment);
  constexpr double kTol = 64 * kEps;  // quantile and a few roundings
  EXPECT_NEAR(ci.lo, std::sqrt(m2 - half), kTol);
  EXPECT_NEAR(ci.hi, std::sqrt(m2 + half), kTol);
  EXPECT_LE(ci.lo, m.rms());
  EXPECT_GE(ci.hi, m.rms());
}

TEST(ScalarMoments, DeltaIntervalLowerEndClipsAtZero) {
  // Heavy tail, small n: m2 - z sqrt(Var) < 0, so the lower end is 0.
  const ScalarMoments m = one_pass({0.0, 0.0, 0.0, 0.0, 10.0});
  const RmsInterval ci = m.rms_interval(0.95);
  EXPECT_EQ(ci.lo, 0.0);
  EXPECT_GT(ci.hi, m.rms());
}

TEST(ScalarMoments, ChiSquareIntervalMatchesTextbook) {
  // Golden quantiles from mpmath (40 digits), reproduced by:
  //   import mpmath as mp; mp.mp.dps = 40
  //   cdf = lambda x, k: mp.gammainc(k/2, 0, x/2, regularized=True)
  //   q = lambda p, k, x0: mp.findroot(lambda x: cdf(x, k) - p, x0)
  //   q(0.025,10,3.2) = 3.246972780236841076, q(0.975,10,20.5) = 20.48317735080739655
  //   q(0.05,5,1.1) = 1.145476226061769250,  q(0.95,5,11) = 11.07049769351635418
  // Printed tables (e.g. NIST/SEMATECH e-Handbook 1.3.6.7.4) give 3.247,
  // 20.483, 1.145, 11.070.
  struct Case {
    double value;      // every value equal, so n m2 = n value^2
    std::size_t n;
    double confidence;
    double chi2_lower;  // chi^2_{a/2}(n)
    double chi2_upper;  // chi^2_{1-a/2}(n)
    double table_lower;
    double table_upper;
  };
  constexpr std::array<Case, 2> cases{{
      {1.0, 10, 0.95, 3.246972780236841076, 20.48317735080739655, 3.247, 20.483},
      {2.0, 5, 0.90, 1.145476226061769250, 11.07049769351635418, 1.145, 11.070},
  }};
  constexpr double kTol = 1e-12;  // Boost.Math quantiles are accurate to ~1e-15
  constexpr double kTableTol = 5e-4;  // half a unit in the last printed digit
  for (const Case& c : cases) {
    ScalarMoments m;
    for (std::size_t i = 0; i < c.n; ++i) m.add(i % 2 ? c.value : -c.value);
    const double n_m2 = static_cast<double>(c.n) * c.value * c.value;
    const RmsInterval ci = m.rms_interval(c.confidence, IntervalMethod::ChiSquareGaussian);
    EXPECT_NEAR(ci.lo, std::sqrt(n_m2 / c.chi2_upper), kTol) << "n = " << c.n;
    EXPECT_NEAR(ci.hi, std::sqrt(n_m2 / c.chi2_lower), kTol) << "n = " << c.n;
    // Back out the quantiles and compare with the printed table.
    EXPECT_NEAR(n_m2 / (ci.lo * ci.lo), c.table_upper, kTableTol) << "n = " << c.n;
    EXPECT_NEAR(n_m2 / (ci.hi * ci.hi), c.table_lower, kTableTol) << "n = " << c.n;
  }
}

// ---------------------------------------------------------------- merge

TEST(ScalarMomentsMerge, EqualsOnePassExactlyForDyadicValues) {
  // Values k/8 with |k| <= 1000 make every r^2 and r^4 and all their partial
  // sums exactly representable (< 2^53 units of 2^-12), so the power sums,
  // count, min and max must agree bit for bit under any grouping.
  CounterStream rng(101, Stream::Bootstrap, 0);
  for (int trial = 0; trial < 300; ++trial) {
    const auto n = 1 + static_cast<std::size_t>(rng.uniform01() * 600);
    std::vector<double> values(n);
    for (double& v : values) v = std::floor(rng.uniform(-1000.0, 1001.0)) / 8.0;
    const ScalarMoments a = one_pass(values);
    const ScalarMoments b = merged_in_parts(values, rng);
    ASSERT_EQ(a.count(), b.count());
    ASSERT_EQ(a.min(), b.min());
    ASSERT_EQ(a.max(), b.max());
    ASSERT_EQ(a.sum_squares(), b.sum_squares()) << "trial " << trial;
    ASSERT_EQ(a.sum_fourth_powers(), b.sum_fourth_powers()) << "trial " << trial;
    // Welford vs Chan: rounding only. Both have worst-case error O(n eps)
    // relative to the data scale (Chan, Golub & LeVeque 1983): for the mean
    // relative to |mean| + sd, for M2 relative to M2 + n mean^2 = sum r^2
    // (M2 times the condition number 1 + mean^2/var). Allow 4 n eps.
    const double tol = 4.0 * static_cast<double>(n) * kEps;
    const double scale = std::fabs(a.mean()) + std::sqrt(a.central_m2() / static_cast<double>(n));
    ASSERT_NEAR(a.mean(), b.mean(), tol * scale) << "trial " << trial;
    ASSERT_NEAR(a.central_m2(), b.central_m2(), tol * a.sum_squares()) << "trial " << trial;
  }
}

TEST(ScalarMomentsMerge, EqualsOnePassWithinRoundingForGeneralValues) {
  CounterStream rng(102, Stream::Bootstrap, 0);
  for (int trial = 0; trial < 300; ++trial) {
    const auto n = 2 + static_cast<std::size_t>(rng.uniform01() * 1000);
    std::vector<double> values(n);
    for (double& v : values) v = 10.0 + 3.0 * rng.standard_normal();  // offset mean
    const ScalarMoments a = one_pass(values);
    const ScalarMoments b = merged_in_parts(values, rng);
    ASSERT_EQ(a.count(), b.count());
    ASSERT_EQ(a.min(), b.min());
    ASSERT_EQ(a.max(), b.max());
    // Sums of positive terms regrouped: relative difference <= 2 n eps.
    const double sum_tol = 2.0 * static_cast<double>(n) * kEps;
    ASSERT_NEAR(a.sum_squares(), b.sum_squares(), sum_tol * a.sum_squares());
    ASSERT_NEAR(a.sum_fourth_powers(), b.sum_fourth_powers(), sum_tol * a.sum_fourth_powers());
    // Mean and M2 as in the dyadic test; here the condition number
    // 1 + mean^2/var is about 12.
    const double tol = 4.0 * static_cast<double>(n) * kEps;
    ASSERT_NEAR(a.mean(), b.mean(), tol * (std::fabs(a.mean()) + a.stddev()));
    ASSERT_NEAR(a.central_m2(), b.central_m2(), tol * a.sum_squares());
    ASSERT_NEAR(a.rms(), b.rms(), sum_tol * a.rms());
  }
}

TEST(ScalarMomentsMerge, EmptyIsAnExactIdentity) {
  const ScalarMoments m = one_pass({0.1, -0.7, 3.3});
  ScalarMoments left;
  left.merge(m);
  ScalarMoments right = m;
  right.merge(ScalarMoments{});
  EXPECT_EQ(left.serialize(), m.serialize());
  EXPECT_EQ(right.serialize(), m.serialize());
}

// ---------------------------------------------------------------- serialisation

TEST(ScalarMomentsSerialize, RoundTripIsBitExact) {
  const std::vector<std::vector<double>> sets{
      {},
      {-0.0},
      {1e-310, -1e300, 0.1, 1.0 / 3.0},
      {std::numeric_limits<double>::denorm_min(), std::numeric_limits<double>::max() / 1e10},
  };
  for (const auto& values : sets) {
    const ScalarMoments m = one_pass(values);
    const std::string bytes = m.serialize();
    EXPECT_EQ(bytes.size(), 4u + 7u * 8u);
    const ScalarMoments back = ScalarMoments::deserialize(bytes);
    EXPECT_EQ(back.serialize(), bytes);
    EXPECT_EQ(back.count(), m.count());
  }
  // -0.0 survives with its sign bit.
  const ScalarMoments z = ScalarMoments::deserialize(one_pass({-0.0}).serialize());
  EXPECT_TRUE(std::signbit(z.min()));
}

TEST(ScalarMomentsSerialize, LayoutIsLittleEndian) {
  const std::string bytes = one_pass({1.0}).serialize();
  EXPECT_EQ(bytes.substr(0, 4), "SM01");
  EXPECT_EQ(static_cast<unsigned char>(bytes[4]), 1u);  // n = 1, low byte first
  // mean = 1.0 = 0x3FF0000000000000: last byte of the field is 0x3F.
  EXPECT_EQ(static_cast<unsigned char>(bytes[12 + 7]), 0x3Fu);
}

TEST(ScalarMomentsSerialize, MalformedInputThrows) {
  const std::string good = one_pass({1.0, 2.0}).serialize();
  EXPECT_THROW(ScalarMoments::deserialize(good.substr(0, good.size() - 1)), std::runtime_error);
  EXPECT_THROW(ScalarMoments::deserialize(good + "x"), std::runtime_error);
  std::string bad_tag = good;
  bad_tag[0] = 'X';
  EXPECT_THROW(ScalarMoments::deserialize(bad_tag), std::runtime_error);
  EXPECT_THROW(ScalarMoments::deserialize(""), std::runtime_error);
}

// ---------------------------------------------------------------- coverage
//
// Statistic: the number X of repetitions (out of kReps) whose 95% interval
// contains the true RMS. Distribution: if the interval has coverage 0.95,
// X ~ Binomial(kReps, 0.95). Acceptance region [lo, hi] with
// P(X < lo) <= a/2 and P(X > hi) <= a/2, a = kFamilyAlpha / kAssertions
// (Bonferroni over this file's coverage assertions), so a correct interval
// fails with probability <= 1e-6 overall. Fixed seeds.
//
// The delta method is asymptotic: at n = 200 its coverage differs from 0.95
// by O(1/sqrt(n)) (about 0.005-0.01 here), inside the +-0.024 acceptance
// half-width; a larger error would be a real defect at the sample counts we
// run. The chi-square interval is exact for normal data.
//
// Power companions (each must *fail* the same check):
//  - chi-square interval on uniform data: its half-width is sqrt(2/0.8)
//    times too wide (Var(r^2)/m2^2 is 2 for normal, 0.8 for uniform), so its
//    coverage is P(|Z| < 1.96 * 1.58) = 0.998 asymptotically;
//  - delta interval on normal data with sigma 10% too large: coverage about
//    0.6 (RMS half-width ~ 1.96/sqrt(2n) = 9.8%).
// The power, P(X outside [lo, hi]) at conservative alternative coverages
// (0.99 and 0.80), is computed and required to be >= 0.999.

constexpr double kFamilyAlpha = 1e-6;
constexpr int kAssertions = 3;  // normal+delta, uniform+delta, normal+chi-square
constexpr int kReps = 2000;
constexpr std::size_t kSamplesPerRep = 200;
constexpr double kConfidence = 0.95;

struct Acceptance {
  int lo;
  int hi;
};

Acceptance binomial_acceptance(int reps, double p, double alpha) {
  const boost::math::binomial_distribution<double> bin(reps, p);
  Acceptance a{0, reps};
  while (a.lo < reps && boost::math::cdf(bin, a.lo) <= alpha / 2) ++a.lo;  // P(X <= lo) > a/2
  // a.lo is now the smallest k with P(X <= k) > a/2, so P(X < a.lo) <= a/2.
  while (a.hi > 0 && boost::math::cdf(boost::math::complement(bin, a.hi - 1)) <= alpha / 2) --a.hi;
  // a.hi is the smallest k with P(X > k) <= a/2.
  return a;
}

double acceptance_probability(const Acceptance& a, int reps, double p) {
  const boost::math::binomial_distribution<double> bin(reps, p);
  const double below = a.lo > 0 ? boost::math::cdf(bin, a.lo - 1) : 0.0;
  return boost::math::cdf(bin, a.hi) - below;
}

enum class Draw { Normal, Uniform };

// Number of repetitions whose interval contains `true_rms`; the data have
// RMS `data_rms` (normal sigma, or uniform on +-sqrt(3) data_rms).
int covered_count(Draw draw, double data_rms, double true_rms, IntervalMethod method,
                  std::uint64_t seed) {
  int covered = 0;
  for (int rep = 0; rep < kReps; ++rep) {
    CounterStream rng(seed, Stream::Bootstrap, static_cast<std::uint64_t>(rep));
    ScalarMoments m;
    for (std::size_t i = 0; i < kSamplesPerRep; ++i) {
      const double r = draw == Draw::Normal
                           ? data_rms * rng.standard_normal()
                           : rng.uniform(-std::sqrt(3.0), std::sqrt(3.0)) * data_rms;
      m.add(r);
    }
    const RmsInterval ci = m.rms_interval(kConfidence, method);
    if (ci.lo <= true_rms && true_rms <= ci.hi) ++covered;
  }
  std::cout << "covered " << covered << " of " << kReps << "\n";
  return covered;
}

class RmsCoverage : public ::testing::Test {
 protected:
  const Acceptance accept =
      binomial_acceptance(kReps, kConfidence, kFamilyAlpha / kAssertions);
};

TEST_F(RmsCoverage, AcceptanceRegionIsSensible) {
  // Expected about 1900 +- 5.3 sd (sd = 9.7).
  EXPECT_GT(accept.lo, 1840);
  EXPECT_LT(accept.lo, 1900);
  EXPECT_GT(accept.hi, 1900);
  EXPECT_LT(accept.hi, 1960);
  EXPECT_GE(acceptance_probability(accept, kReps, kConfidence), 1.0 - kFamilyAlpha / kAssertions);
  std::cout << "acceptance region [" << accept.lo << ", " << accept.hi << "]\n";
}

TEST_F(RmsCoverage, DeltaMethodNormal) {
  const int x = covered_count(Draw::Normal, 1.0, 1.0, IntervalMethod::DeltaFourthMoment, 501);
  EXPECT_GE(x, accept.lo);
  EXPECT_LE(x, accept.hi);
}

TEST_F(RmsCoverage, DeltaMethodUniform) {
  const int x = covered_count(Draw::Uniform, 1.0, 1.0, IntervalMethod::DeltaFourthMoment, 502);
  EXPECT_GE(x, accept.lo);
  EXPECT_LE(x, accept.hi);
}

TEST_F(RmsCoverage, ChiSquareNormal) {
  const int x = covered_count(Draw::Normal, 1.0, 1.0, IntervalMethod::ChiSquareGaussian, 503);
  EXPECT_GE(x, accept.lo);
  EXPECT_LE(x, accept.hi);
}

TEST_F(RmsCoverage, PowerChiSquareOnUniformFails) {
  constexpr double kAltCoverage = 0.99;  // conservative; asymptotically 0.998
  const double power = 1.0 - acceptance_probability(accept, kReps, kAltCoverage);
  ASSERT_GE(power, 0.999);
  const int x = covered_count(Draw::Uniform, 1.0, 1.0, IntervalMethod::ChiSquareGaussian, 504);
  EXPECT_GT(x, accept.hi) << "the coverage check cannot tell the chi-square interval is wrong "
                             "for uniform data";
}

TEST_F(RmsCoverage, PowerTenPercentScaleErrorFails) {
  constexpr double kAltCoverage = 0.80;  // conservative; asymptotically about 0.6
  const double power = 1.0 - acceptance_probability(accept, kReps, kAltCoverage);
  ASSERT_GE(power, 0.999);
  const int x = covered_count(Draw::Normal, 1.1, 1.0, IntervalMethod::DeltaFourthMoment, 505);
  EXPECT_LT(x, accept.lo) << "the coverage check cannot detect a 10% RMS error";
}

}  // namespace
}  // namespace insmc::mc
