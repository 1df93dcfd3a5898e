#pragma once
/// Streaming, mergeable statistics of one Monte Carlo output (one scheme ×
/// system × axis × time): count, mean and standard deviation, RMS with its
/// confidence interval, minimum, maximum and the 95th percentile of |r|.
///
/// Values arrive in blocks of a fixed size (the engine's), each block summed
/// in double in index order and then added to exact fixed-point totals
/// (exact_sum.h): merging is exactly associative, so the state is the same
/// bits for any split of the blocks across threads or processes.
/// Memory is independent of the sample count.
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "montecarlo/study/aggregate/exact_sum.h"

namespace insmc::mc {

/// A fixed, mergeable histogram of |r| on [0, kRange·scale) with an
/// overflow count: the p-quantile of |r| is read to within one bin,
/// kRange·scale/kBins (scale: the output's predicted RMS).
struct AbsHistogramLayout {
  static constexpr int kBins = 4096;
  static constexpr double kRange = 12.0;
};

struct OutputSummary {
  std::uint64_t n = 0;
  double mean = 0, std = 0, rms = 0, rms_lo = 0, rms_hi = 0, min = 0, max = 0, p95_abs = 0;
  /// True when p95 lies beyond the histogram (heavy tails): p95_abs is then
  /// the maximum |r|, an upper bound.
  bool p95_is_upper_bound = false;
};

class OutputStats {
 public:
  /// `shift`: a reference value near the mean (the predicted mean), removed
  /// before summing so that the variance does not cancel; `scale` > 0 sets
  /// the histogram range (the predicted RMS, or any positive scale).
  OutputStats(double shift, double scale);

  /// Adds n values (one block), summed in index order.
  void add_block(const double* values, std::size_t n);
  void merge(const OutputStats& other);
  /// The same, taking `other`'s state whole when this one has none yet.
  void merge(OutputStats&& other);

  /// confidence in (0, 1); `gaussian` selects the exact chi-square interval
  /// (valid for zero-mean normal outputs) instead of the delta method.
  OutputSummary summarize(double confidence, bool gaussian = false) const;

  std::uint64_t count() const { return n_; }
  double sum_squares() const { return sum_r2_.value(); }
  double sum_fourth_powers() const { return sum_r4_.value(); }

  void append_to(std::string& out) const;
  static OutputStats read_from(std::string_view bytes, std::size_t& pos);

  friend bool operator==(const OutputStats&, const OutputStats&);

 private:
  double shift_, scale_, inv_bin_width_;
  std::uint64_t n_ = 0;
  ExactSum sum_d_, sum_d2_, sum_r2_, sum_r4_;  // d = r − shift
  double min_, max_;
  // kBins + 1 (overflow last), allocated with the first value: a study holds
  // thousands of outputs in several partial states, most never filled.
  std::vector<std::uint64_t> hist_;
};

/// Two-sided confidence interval for an RMS from n, Σr², Σr⁴: the delta
/// method with the fourth moment on the log scale, against Student's t with
/// n − 1 degrees of freedom (default, valid for non-normal r), or the exact
/// chi-square interval for zero-mean normal r. {NaN, NaN} for n < 2.
struct RmsBounds {
  double lo, hi;
};
RmsBounds rms_confidence_interval(std::uint64_t n, double sum_r2, double sum_r4, double confidence,
                                  bool gaussian);

}  // namespace insmc::mc
