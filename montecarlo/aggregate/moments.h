#pragma once
/// Streaming, mergeable moments of one Monte Carlo output quantity
/// (STYLE conventions 8 and 9).
///
/// Kept per quantity: the count n; the mean and central second moment M2
/// (Welford's update per value, the pairwise update of Chan, Golub and
/// LeVeque (1979) on merge); the power sums sum r^2 and sum r^4 (for the RMS
/// and its confidence interval); min and max.
///
/// The power sums are plain sums of non-negative terms, so their relative
/// rounding error is at most about n * epsilon (1e-10 at n = 1e6), far
/// below the statistical half-width ~1/sqrt(n) they are used with.
///
/// Determinism: `merge` is associative in exact arithmetic only; the engine
/// fixes the merge order (block order), so the bits do not depend on
/// scheduling. Merging with an empty aggregator is an exact identity.
#include <cstdint>
#include <string>
#include <string_view>

namespace insmc::mc {

/// A confidence interval for an RMS, in the units of the quantity.
struct RmsInterval {
  double lo;
  double hi;
};

enum class IntervalMethod {
  /// Delta method on the mean of r^2 with the sample fourth moment: valid for
  /// any distribution with finite fourth moment as n grows (CLT for the mean
  /// of r^2). m2 = sum r^2 / n, m4 = sum r^4 / n, Var(RMS^2) ~ (m4 - m2^2)/n;
  /// RMS^2 in m2 -/+ z sqrt(Var), lower end clipped at 0, then square roots.
  DeltaFourthMoment,
  /// Exact when r is zero-mean normal: n RMS^2 / sigma^2 ~ chi^2(n), giving
  /// sigma^2 in [n m2 / chi^2_{1-a/2}(n), n m2 / chi^2_{a/2}(n)], then square
  /// roots. Too wide for the default uniform draws (lighter tails).
  ChiSquareGaussian,
};

class ScalarMoments {
 public:
  /// Adds one value (must be finite: a NaN or inf means an upstream bug).
  void add(double r);
  /// Folds `other` into *this (Chan et al. pairwise update for mean and M2).
  void merge(const ScalarMoments& other);

  std::uint64_t count() const { return n_; }
  /// Sample mean; NaN if n == 0.
  double mean() const;
  /// Sample standard deviation with n - 1 in the denominator; NaN if n < 2.
  double stddev() const;
  /// Central second moment M2 = sum (r - mean)^2.
  double central_m2() const { return m2_; }
  /// sqrt(sum r^2 / n); NaN if n == 0.
  double rms() const;
  /// Smallest and largest value added; NaN if n == 0.
  double min() const;
  double max() const;
  double sum_squares() const { return sum_r2_; }
  double sum_fourth_powers() const { return sum_r4_; }

  /// Two-sided interval for the RMS at `confidence` (e.g. 0.95), which must
  /// lie in (0, 1). Returns {NaN, NaN} when n < 2.
  RmsInterval rms_interval(double confidence,
                           IntervalMethod method = IntervalMethod::DeltaFourthMoment) const;

  /// Byte string: a format tag, n as u64, then mean, M2, sum r^2, sum r^4,
  /// min, max as IEEE-754 binary64 bit patterns, all little-endian.
  /// deserialize(serialize()) reproduces every bit.
  std::string serialize() const;
  /// Throws std::runtime_error on a malformed or truncated string.
  static ScalarMoments deserialize(std::string_view bytes);

  friend bool operator==(const ScalarMoments&, const ScalarMoments&) = default;

 private:
  std::uint64_t n_ = 0;
  double mean_ = 0.0;
  double m2_ = 0.0;
  double sum_r2_ = 0.0;
  double sum_r4_ = 0.0;
  double min_ = 0.0;  ///< meaningful only when n_ > 0
  double max_ = 0.0;  ///< meaningful only when n_ > 0
};

}  // namespace insmc::mc
