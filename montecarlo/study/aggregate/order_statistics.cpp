#include "montecarlo/study/aggregate/order_statistics.h"

#include <algorithm>
#include <array>
#include <boost/math/distributions/binomial.hpp>
#include <cmath>
#include <limits>

#include "lib/common/assert.h"

namespace insmc::mc {

std::uint64_t nearest_rank(std::uint64_t n, double p) {
  INSMC_ASSERT(n >= 1 && p > 0 && p < 1, "nearest_rank(n = {}, p = {})", n, p);
  // k = ceil(p·n), kept within [1, n] against rounding of p·n.
  const auto k = static_cast<std::uint64_t>(std::ceil(p * static_cast<double>(n)));
  return std::clamp<std::uint64_t>(k, 1, n);
}

RankInterval quantile_rank_interval(std::uint64_t n, double p, double confidence) {
  INSMC_ASSERT(n >= 1 && p > 0 && p < 1 && confidence > 0 && confidence < 1,
               "quantile_rank_interval(n = {}, p = {}, confidence = {})", n, p, confidence);
  const boost::math::binomial_distribution<double> b(static_cast<double>(n), p);
  const double tail = (1 - confidence) / 2;  // α/2 on each side
  // Lower end: the largest l in [0, n] with P(B ≤ l − 1) ≤ α/2 (l = 0 always
  // qualifies: P(B ≤ −1) = 0). P(B ≤ k) grows with k: bisect on l.
  std::uint64_t ok = 0, bad = n + 1;
  while (bad - ok > 1) {
    const std::uint64_t mid = ok + (bad - ok) / 2;
    if (boost::math::cdf(b, static_cast<double>(mid - 1)) <= tail) ok = mid;
    else bad = mid;
  }
  const std::uint64_t lo = ok;
  // Upper end: the smallest u in [1, n + 1] with P(B ≥ u) ≤ α/2 (u = n + 1
  // always qualifies: P(B ≥ n + 1) = 0). P(B ≥ u) = P(B > u − 1) falls with u.
  std::uint64_t good = n + 1, fail = 0;
  while (good - fail > 1) {
    const std::uint64_t mid = fail + (good - fail) / 2;
    if (boost::math::cdf(boost::math::complement(b, static_cast<double>(mid - 1))) <= tail) good = mid;
    else fail = mid;
  }
  return {lo, good};
}

QuantileEstimate quantile_with_interval(std::span<float> values, double p, double confidence, double support_lo) {
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  const std::uint64_t n = values.size();
  if (n == 0) return {kNaN, kNaN, kNaN};
  const RankInterval r = quantile_rank_interval(n, p, confidence);
  const std::uint64_t k = nearest_rank(n, p);
  // The three order statistics by successive selection, lowest rank first:
  // after selecting rank q everything beyond position q − 1 is ≥ X_(q).
  std::array<std::uint64_t, 3> ranks = {r.lo, k, r.hi};
  std::array<double, 3> at{};
  std::uint64_t from = 0;
  for (std::size_t i = 0; i < ranks.size(); ++i) {
    const std::uint64_t q = ranks[i];
    if (q == 0) {
      at[i] = support_lo;
      continue;
    }
    if (q > n) {
      at[i] = std::numeric_limits<double>::infinity();
      continue;
    }
    const auto first = values.begin() + static_cast<std::ptrdiff_t>(from);
    const auto nth = values.begin() + static_cast<std::ptrdiff_t>(q - 1);
    if (q - 1 >= from) std::nth_element(first, nth, values.end());
    at[i] = *nth;
    from = q;
  }
  return {at[1], at[0], at[2]};
}

}  // namespace insmc::mc
