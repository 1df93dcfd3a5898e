#pragma once
/// Mergeable, fixed-memory, deterministic sketch of the quantiles of |r|
/// (e.g. the p95 of an absolute error) for one output quantity.
///
/// Quantile definition (both modes): the nearest-rank quantile of the n
/// values |r|, i.e. the k-th smallest with k = ceil(q n) (1-based), clamped
/// to [1, n]; q = 0 gives the minimum.
///
/// Two modes:
///  - Exact: while n <= kExactCapacity (4096) the values are stored and a
///    query returns the exact nearest-rank quantile.
///  - Bucketed: beyond that, a log-bucketed histogram of |r| with relative
///    accuracy alpha = kRelativeAccuracy = 0.5% (DDSketch, Masson, Rim & Lee,
///    VLDB 2019): gamma = (1 + alpha) / (1 - alpha); value v > 0 goes to
///    bucket i = ceil(ln v / ln gamma), i.e. gamma^(i-1) < v <= gamma^i; the
///    query returns the bucket's representative 2 gamma^i / (gamma + 1),
///    clamped to the exact [min |r|, max |r|]; exact zeros are counted apart
///    and returned as 0.
///
/// Stated error: in bucketed mode the returned value x' and the exact
/// nearest-rank quantile x satisfy |x' - x| <= alpha x (plus a few ulp from
/// evaluating the logarithm near a bucket edge), provided
/// x > max|r| / gamma^(kMaxBuckets - 1) ~ max|r| / 4.8e8. Values below that
/// threshold are collapsed into the lowest kept bucket (the "collapsing
/// lowest" store), which bounds memory at kMaxBuckets counts (16 kB; the
/// exact mode holds at most 32 kB and releases it on switching). Quantiles
/// that fall in the collapsed range are only bounded above by the
/// threshold. In exact mode the error is zero.
///
/// Merging adds counts, so the state (and every quantile) is a function of
/// the multiset of values only: building in one pass or merging parts in any
/// order gives identical quantiles and identical serialize() bytes (exact
/// mode serialises the values sorted).
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace insmc::mc {

class QuantileSketch {
 public:
  static constexpr std::size_t kExactCapacity = 4096;
  static constexpr double kRelativeAccuracy = 0.005;  ///< alpha, dimensionless
  static constexpr std::size_t kMaxBuckets = 2000;

  /// Adds |r| (r must be finite).
  void add(double r);
  /// Folds `other` into *this.
  void merge(const QuantileSketch& other);

  std::uint64_t count() const { return n_; }
  /// True while the values are stored exactly (n <= kExactCapacity).
  bool is_exact() const { return exact_; }
  /// Number of histogram buckets in use (0 in exact mode), <= kMaxBuckets.
  std::size_t bucket_count() const { return counts_.size(); }

  /// Nearest-rank q-quantile of |r|, q in [0, 1]; NaN if empty. See the
  /// header comment for the error bound.
  double abs_quantile(double q) const;

  /// Little-endian byte string (format tag, mode, counts, exact doubles);
  /// canonical for a given multiset of values. Round trip is bit-exact.
  std::string serialize() const;
  /// Throws std::runtime_error on a malformed or truncated string.
  static QuantileSketch deserialize(std::string_view bytes);

 private:
  void add_value_to_buckets(double v);
  void add_index(std::int64_t i, std::uint64_t count);
  void switch_to_buckets();
  static std::int32_t bucket_index(double v);

  std::uint64_t n_ = 0;
  double min_abs_ = 0.0;  ///< exact smallest |r| (valid when n_ > 0)
  double max_abs_ = 0.0;  ///< exact largest |r| (valid when n_ > 0)
  bool exact_ = true;
  std::vector<double> values_;  ///< exact mode: the |r| in insertion order
  // Bucketed mode: counts_[j] counts bucket index lo_ + j; the highest kept
  // index is lo_ + counts_.size() - 1 (the largest index seen) and
  // lo_ = max(smallest index seen, highest - kMaxBuckets + 1).
  std::uint64_t zero_count_ = 0;
  std::int32_t lo_ = 0;
  std::vector<std::uint64_t> counts_;
};

}  // namespace insmc::mc
