#pragma once
/// Sample quantiles and their distribution-free confidence intervals from
/// order statistics (docs/outputs.md, "Accuracy metrics").
///
/// The estimate of the p-quantile ξ_p of n i.i.d. values is the nearest-rank
/// order statistic X_(k), k = ceil(p·n). Its interval is [X_(l), X_(u)]:
/// with B = #{X_i ≤ ξ_p} ~ Binomial(n, p), X_(l) > ξ_p exactly when B ≤ l − 1
/// and X_(u) < ξ_p exactly when B ≥ u (continuous X), so choosing
/// P(B ≤ l − 1) ≤ α/2 and P(B ≥ u) ≤ α/2 gives coverage ≥ 1 − α whatever the
/// distribution of X.
#include <cstdint>
#include <span>

namespace insmc::mc {

/// 1-based ranks of an interval's ends. lo = 0: no order statistic is low
/// enough (the interval starts at the support's lower end); hi = n + 1: none
/// is high enough (the interval is unbounded above).
struct RankInterval {
  std::uint64_t lo, hi;
};

/// The nearest-rank index k = ceil(p·n), at least 1; n ≥ 1, p in (0, 1).
std::uint64_t nearest_rank(std::uint64_t n, double p);

/// The equal-tailed order-statistic interval for ξ_p: the largest l with
/// P(B ≤ l − 1) ≤ α/2 and the smallest u with P(B ≥ u) ≤ α/2, B ~ Bin(n, p),
/// α = 1 − confidence (Boost.Math's binomial distribution).
RankInterval quantile_rank_interval(std::uint64_t n, double p, double confidence);

/// A quantile estimate and its confidence interval.
struct QuantileEstimate {
  double value, lo, hi;
};

/// ξ_p of `values` with its interval (above). Reorders `values` (partial
/// selection, O(n)). `support_lo` stands in for rank 0 (0 for a magnitude);
/// rank n + 1 is +inf. NaN everywhere for no values.
QuantileEstimate quantile_with_interval(std::span<float> values, double p, double confidence, double support_lo);

}  // namespace insmc::mc
