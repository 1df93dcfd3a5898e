// Statistical test: the coverage of the run's RMS confidence interval
// ([rms_lo, rms_hi]: the delta method with the fourth moment,
// 95%), over many independent runs of a small study.
//
// Statistic: X, the number of the kRuns runs (seeds kFirstSeed ...
// kFirstSeed + 199, n = 2000 samples each; scheme none, system 1, report
// times only, linear fidelity, uniform draws) whose interval for the horizontal
// output at 84 min contains the exact RMS of the linear map
// (StudyMap::predicted_rms).
// Sampling distribution: the runs are independent (different seeds give
// independent Philox streams), so if the interval has coverage 0.95,
// X ~ Binomial(200, 0.95). The delta-method interval is asymptotic; at
// n = 2000 its coverage differs from 0.95 by O(1/sqrt(n)), far inside the
// acceptance region (about 0.87 .. 1).
// α: 1e-6 for this file (one assertion): the acceptance region [lo, hi]
// has P(X < lo) ≤ α/2 and P(X > hi) ≤ α/2 under Binomial(200, 0.95).
// Power companion: the same runs, the same check, against an RMS 10% too
// large. Its coverage p_alt is computed from the exact moments (normal
// approximation of the mean of r², Var(r²) from StudyMap::predicted_var_r2)
// and, with a 0.25 allowance for that approximation, the probability that X
// falls outside [lo, hi] must be ≥ 0.999 before the test relies on it.
#include <gtest/gtest.h>

#include <algorithm>
#include <boost/math/distributions/binomial.hpp>
#include <boost/math/distributions/normal.hpp>
#include <cmath>
#include <cstdint>
#include <iostream>

#include "lib/compensation/scheme.h"
#include "montecarlo/study/engine/engine.h"

namespace insmc::mc {
namespace {

constexpr double kAlpha = 1e-6;
constexpr int kRuns = 200;
constexpr std::uint64_t kFirstSeed = 7000;
constexpr std::uint64_t kSamplesPerRun = 2000;
constexpr double kConfidence = 0.95;
constexpr double kWrongRmsFactor = 1.1;
constexpr double kPowerRequired = 0.999;
constexpr double kApproximationAllowance = 0.25;  // added to the computed p_alt

struct Acceptance {
  int lo, hi;
};

Acceptance binomial_acceptance(int runs, double p, double alpha) {
  const boost::math::binomial_distribution<double> bin(runs, p);
  Acceptance a{0, runs};
  while (a.lo < runs && boost::math::cdf(bin, a.lo) <= alpha / 2) ++a.lo;
  // a.lo is the smallest k with P(X <= k) > α/2, so P(X < a.lo) <= α/2.
  while (a.hi > 0 && boost::math::cdf(boost::math::complement(bin, a.hi - 1)) <= alpha / 2) --a.hi;
  // a.hi is the smallest k with P(X > k) <= α/2.
  return a;
}

double acceptance_probability(const Acceptance& a, int runs, double p) {
  const boost::math::binomial_distribution<double> bin(runs, p);
  const double below = a.lo > 0 ? boost::math::cdf(bin, a.lo - 1) : 0.0;
  return boost::math::cdf(bin, a.hi) - below;
}

TEST(RmsIntervalCoverage, ContainsTheExactRmsAtTheStatedRate) {
  StudyConfig c;
  c.schemes = {Scheme::kNone};  // exactly linear in x: the predicted RMS is exact
  c.systems = {System::kTheodolite};
  c.fidelity = Fidelity::kLinear;
  c.with_grid = false;
  c.samples = kSamplesPerRun;
  c.confidence = kConfidence;
  c.threads = 2;
  const StudyLayout layout = make_layout(c);
  const StudyMap map(c, layout);
  const std::size_t o = static_cast<std::size_t>(layout.index(0, 0, 2, Axis::kHorizontal));
  ASSERT_DOUBLE_EQ(layout.times_s[2], 84 * 60.0);
  const double exact_rms = map.predicted_rms()[o];
  const double wrong_rms = kWrongRmsFactor * exact_rms;

  const Acceptance accept = binomial_acceptance(kRuns, kConfidence, kAlpha);
  ASSERT_GE(acceptance_probability(accept, kRuns, kConfidence), 1 - kAlpha);

  // Power companion, computed before the runs: the interval for RMS² is
  // m̂2 ± z ŝ with m̂2 ~ N(m2, v/n); it contains wrong² with probability
  // about Φ(d + z) − Φ(d − z), d = (wrong² − m2)/sqrt(v/n).
  const double n = static_cast<double>(kSamplesPerRun);
  const double m2 = exact_rms * exact_rms, sd = std::sqrt(map.predicted_var_r2()[o] / n);
  const boost::math::normal nd;
  const double z = boost::math::quantile(boost::math::complement(nd, (1 - kConfidence) / 2));
  const double d = (wrong_rms * wrong_rms - m2) / sd;
  const double p_alt = boost::math::cdf(nd, d + z) - boost::math::cdf(nd, d - z);
  const double p_bound = std::min(1.0, p_alt + kApproximationAllowance);
  const double power = 1 - acceptance_probability(accept, kRuns, p_bound);
  std::cout << "acceptance region [" << accept.lo << ", " << accept.hi << "]; wrong-RMS coverage " << p_alt
            << " (bounded by " << p_bound << "), power " << power << "\n";
  ASSERT_GE(power, kPowerRequired);

  int covered = 0, covered_wrong = 0;
  for (int run = 0; run < kRuns; ++run) {
    c.seed = kFirstSeed + static_cast<std::uint64_t>(run);
    const StudyAccumulator acc = run_blocks(c, map, 0, block_count(c.samples));
    const OutputSummary s = acc.outputs()[o].summarize(c.confidence);
    ASSERT_EQ(s.n, kSamplesPerRun);
    covered += s.rms_lo <= exact_rms && exact_rms <= s.rms_hi;
    covered_wrong += s.rms_lo <= wrong_rms && wrong_rms <= s.rms_hi;
  }
  std::cout << "covered " << covered << " of " << kRuns << "; the 10% wrong RMS " << covered_wrong << "\n";
  EXPECT_GE(covered, accept.lo);
  EXPECT_LE(covered, accept.hi);
  EXPECT_TRUE(covered_wrong < accept.lo || covered_wrong > accept.hi)
      << "the coverage check cannot tell an RMS 10% too large";
}

}  // namespace
}  // namespace insmc::mc
