#pragma once
// The acceptance region of a coverage count: X intervals out of `reps`
// contain the truth, X ~ Binomial(reps, coverage) (Boost.Math's binomial).
#include <boost/math/distributions/binomial.hpp>

namespace insmc::mc::testing {

struct Acceptance {
  int lo;
  int hi;
};

/// [lo, hi] with P(X < lo) <= alpha/2 and P(X > hi) <= alpha/2, X ~ Bin(reps, p).
inline Acceptance binomial_acceptance(int reps, double p, double alpha) {
  const boost::math::binomial_distribution<double> bin(reps, p);
  Acceptance a{0, reps};
  while (a.lo < reps && boost::math::cdf(bin, a.lo) <= alpha / 2) ++a.lo;
  // a.lo is the smallest k with P(X <= k) > a/2, so P(X < a.lo) <= a/2.
  while (a.hi > 0 && boost::math::cdf(boost::math::complement(bin, a.hi - 1)) <= alpha / 2) --a.hi;
  // a.hi is the smallest k with P(X > k) <= a/2.
  return a;
}

/// P(lo <= X <= hi) for X ~ Bin(reps, p).
inline double acceptance_probability(const Acceptance& a, int reps, double p) {
  const boost::math::binomial_distribution<double> bin(reps, p);
  const double below = a.lo > 0 ? boost::math::cdf(bin, a.lo - 1) : 0.0;
  return boost::math::cdf(bin, a.hi) - below;
}

}  // namespace insmc::mc::testing
