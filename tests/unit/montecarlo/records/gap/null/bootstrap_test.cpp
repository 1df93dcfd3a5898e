// Tests for montecarlo/records/gap/null/bootstrap.h: a value beyond the
// critical value and a p-value at most alpha are one decision.
#include "montecarlo/records/gap/null/bootstrap.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace insmc::gap {
namespace {

TEST(CriticalValue, BeyondItIsPAtMostAlpha) {
  std::mt19937_64 rng(5);
  std::gamma_distribution<double> skewed(2.0, 1.0);
  for (const std::size_t n : {19u, 200u, 2000u, 2001u}) {
    std::vector<double> null(n);
    for (double& v : null) v = skewed(rng);
    for (const double alpha : {0.01, 0.05, 0.1, 0.0049}) {
      const double critical = critical_value(null, alpha);
      // Every null value and points between them: the decision flips at
      // the critical value and nowhere else.
      std::vector<double> probes = null;
      for (double v : null) probes.push_back(std::nextafter(v, 1e9));
      for (double observed : probes)
        EXPECT_EQ(observed > critical, p_value_of(observed, null) <= alpha)
            << "n " << n << " alpha " << alpha << " observed " << observed << " critical " << critical;
    }
  }
}

TEST(CriticalValue, NoPCanReachAnAlphaBelowOneOverTheFilesPlusOne) {
  const std::vector<double> null(99, 1.0);
  EXPECT_TRUE(std::isinf(critical_value(null, 0.005)));  // least p 1/100
  EXPECT_EQ(critical_value(null, 0.02), 1.0);
}

}  // namespace
}  // namespace insmc::gap
