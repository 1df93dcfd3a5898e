#include "montecarlo/aggregate/quantile_sketch.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "lib/common/assert.h"
#include "montecarlo/aggregate/byte_io.h"

namespace insmc::mc {

namespace {

constexpr double kGamma =
    (1.0 + QuantileSketch::kRelativeAccuracy) / (1.0 - QuantileSketch::kRelativeAccuracy);
const double kLogGamma = std::log(kGamma);
constexpr std::uint32_t kFormatTag = 0x31305351u;  // "QS01" little-endian
constexpr std::uint32_t kModeExact = 0;
constexpr std::uint32_t kModeBuckets = 1;
constexpr auto kMaxBucketCount = static_cast<std::int64_t>(QuantileSketch::kMaxBuckets);

}  // namespace

std::int32_t QuantileSketch::bucket_index(double v) {
  // gamma^(i-1) < v <= gamma^i. |ln v| <= 745 for positive doubles, so
  // |i| <= 74500 fits easily.
  return static_cast<std::int32_t>(std::ceil(std::log(v) / kLogGamma));
}

void QuantileSketch::add(double r) {
  INSMC_ASSERT(std::isfinite(r), "QuantileSketch::add: non-finite value {}", r);
  const double v = std::fabs(r);
  if (n_ == 0) {
    min_abs_ = v;
    max_abs_ = v;
  } else {
    min_abs_ = std::min(min_abs_, v);
    max_abs_ = std::max(max_abs_, v);
  }
  ++n_;
  if (exact_) {
    if (n_ <= kExactCapacity) {
      values_.push_back(v);
      return;
    }
    switch_to_buckets();
  }
  add_value_to_buckets(v);
}

void QuantileSketch::merge(const QuantileSketch& other) {
  if (other.n_ == 0) return;
  if (n_ == 0) {
    *this = other;
    return;
  }
  min_abs_ = std::min(min_abs_, other.min_abs_);
  max_abs_ = std::max(max_abs_, other.max_abs_);
  n_ += other.n_;
  if (exact_ && other.exact_ && n_ <= kExactCapacity) {
    values_.insert(values_.end(), other.values_.begin(), other.values_.end());
    return;
  }
  if (exact_) switch_to_buckets();
  if (other.exact_) {
    for (const double v : other.values_) add_value_to_buckets(v);
  } else {
    zero_count_ += other.zero_count_;
    for (std::size_t j = 0; j < other.counts_.size(); ++j) {
      if (other.counts_[j] != 0) {
        add_index(std::int64_t{other.lo_} + static_cast<std::int64_t>(j), other.counts_[j]);
      }
    }
  }
}

void QuantileSketch::switch_to_buckets() {
  exact_ = false;
  for (const double v : values_) add_value_to_buckets(v);
  std::vector<double>().swap(values_);
}

void QuantileSketch::add_value_to_buckets(double v) {
  if (v == 0.0) {
    ++zero_count_;
    return;
  }
  add_index(bucket_index(v), 1);
}

// Keeps the invariant documented in the header: highest kept index = largest
// index seen, lo_ = max(smallest index seen, highest - kMaxBuckets + 1), and
// every count sits at max(its index, lo_). The state then depends only on
// the multiset of indices added, not on the order.
void QuantileSketch::add_index(std::int64_t i, std::uint64_t count) {
  if (counts_.empty()) {
    lo_ = static_cast<std::int32_t>(i);
    counts_.assign(1, count);
    return;
  }
  const std::int64_t lo = lo_;
  const std::int64_t hi = lo + static_cast<std::int64_t>(counts_.size()) - 1;
  if (i > hi) {
    const std::int64_t new_lo = std::max(lo, i - kMaxBucketCount + 1);
    if (new_lo > lo) {
      // Collapse every bucket below new_lo into bucket new_lo.
      const auto below = static_cast<std::size_t>(new_lo - lo);
      if (below >= counts_.size()) {
        std::uint64_t total = 0;
        for (const std::uint64_t c : counts_) total += c;
        counts_.assign(1, total);
      } else {
        std::uint64_t folded = 0;
        for (std::size_t j = 0; j < below; ++j) folded += counts_[j];
        counts_.erase(counts_.begin(), counts_.begin() + static_cast<std::ptrdiff_t>(below));
        counts_[0] += folded;
      }
      lo_ = static_cast<std::int32_t>(new_lo);
    }
    counts_.resize(static_cast<std::size_t>(i - lo_ + 1), 0);
    counts_.back() += count;
    return;
  }
  if (i < lo) {
    const std::int64_t target = std::max(i, hi - kMaxBucketCount + 1);
    if (target < lo) {
      counts_.insert(counts_.begin(), static_cast<std::size_t>(lo - target), 0);
      lo_ = static_cast<std::int32_t>(target);
    }
    counts_[static_cast<std::size_t>(target - lo_)] += count;
    return;
  }
  counts_[static_cast<std::size_t>(i - lo)] += count;
}

double QuantileSketch::abs_quantile(double q) const {
  INSMC_ASSERT(q >= 0.0 && q <= 1.0, "abs_quantile: q = {} outside [0, 1]", q);
  if (n_ == 0) return std::numeric_limits<double>::quiet_NaN();
  // Nearest rank k = ceil(q n), clamped to [1, n] (1-based).
  const double k_real = std::ceil(q * static_cast<double>(n_));
  const std::uint64_t k =
      std::clamp<std::uint64_t>(k_real < 1.0 ? 1 : static_cast<std::uint64_t>(k_real), 1, n_);
  if (exact_) {
    std::vector<double> sorted = values_;
    const auto nth = sorted.begin() + static_cast<std::ptrdiff_t>(k - 1);
    std::nth_element(sorted.begin(), nth, sorted.end());
    return *nth;
  }
  if (k <= zero_count_) return 0.0;
  std::uint64_t cumulative = zero_count_;
  for (std::size_t j = 0; j < counts_.size(); ++j) {
    cumulative += counts_[j];
    if (cumulative >= k) {
      const double i = static_cast<double>(std::int64_t{lo_} + static_cast<std::int64_t>(j));
      const double representative = 2.0 * std::exp(i * kLogGamma) / (kGamma + 1.0);
      return std::clamp(representative, min_abs_, max_abs_);
    }
  }
  INSMC_ASSERT(false, "abs_quantile: counts sum to {} < n = {}", cumulative, n_);
  return max_abs_;
}

std::string QuantileSketch::serialize() const {
  std::string out;
  byte_io::put_u32(out, kFormatTag);
  byte_io::put_u32(out, exact_ ? kModeExact : kModeBuckets);
  byte_io::put_u64(out, n_);
  byte_io::put_f64(out, min_abs_);
  byte_io::put_f64(out, max_abs_);
  if (exact_) {
    std::vector<double> sorted = values_;
    std::sort(sorted.begin(), sorted.end());
    for (const double v : sorted) byte_io::put_f64(out, v);
  } else {
    byte_io::put_u64(out, zero_count_);
    byte_io::put_u32(out, static_cast<std::uint32_t>(lo_));
    byte_io::put_u64(out, counts_.size());
    for (const std::uint64_t c : counts_) byte_io::put_u64(out, c);
  }
  return out;
}

QuantileSketch QuantileSketch::deserialize(std::string_view bytes) {
  byte_io::Reader in(bytes, "QuantileSketch");
  if (in.u32() != kFormatTag) in.fail("bad format tag");
  const std::uint32_t mode = in.u32();
  if (mode != kModeExact && mode != kModeBuckets) in.fail("bad mode");
  QuantileSketch s;
  s.exact_ = mode == kModeExact;
  s.n_ = in.u64();
  s.min_abs_ = in.f64();
  s.max_abs_ = in.f64();
  if (s.exact_) {
    if (s.n_ > kExactCapacity) in.fail("exact mode with n > capacity");
    s.values_.resize(s.n_);
    for (double& v : s.values_) v = in.f64();
  } else {
    s.zero_count_ = in.u64();
    s.lo_ = static_cast<std::int32_t>(in.u32());
    const std::uint64_t size = in.u64();
    if (size > kMaxBuckets) in.fail("too many buckets");
    s.counts_.resize(size);
    std::uint64_t total = s.zero_count_;
    for (std::uint64_t& c : s.counts_) {
      c = in.u64();
      total += c;
    }
    if (total != s.n_) in.fail("bucket counts do not sum to n");
  }
  in.expect_end();
  return s;
}

}  // namespace insmc::mc
