#include "montecarlo/study/aggregate/output_stats.h"

#include <algorithm>
#include <boost/math/distributions/chi_squared.hpp>
#include <boost/math/distributions/students_t.hpp>
#include <cmath>
#include <limits>
#if defined(__GNUC__) && defined(__x86_64__)
#include <immintrin.h>
#endif

#include "lib/common/assert.h"
#include "montecarlo/study/aggregate/byte_io.h"

namespace insmc::mc {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

}  // namespace

RmsBounds rms_confidence_interval(std::uint64_t n, double sum_r2, double sum_r4, double confidence,
                                  bool gaussian) {
  INSMC_ASSERT(confidence > 0 && confidence < 1, "confidence = {}", confidence);
  if (n < 2) return {kNaN, kNaN};
  const double nd = static_cast<double>(n), m2 = sum_r2 / nd, alpha = 1 - confidence;
  if (gaussian) {
    // n·RMS²/σ² ~ χ²(n) for zero-mean normal r.
    const boost::math::chi_squared chi(nd);
    const double lo2 = nd * m2 / boost::math::quantile(chi, 1 - alpha / 2);
    const double hi2 = nd * m2 / boost::math::quantile(chi, alpha / 2);
    return {std::sqrt(lo2), std::sqrt(hi2)};
  }
  // Delta method on the log scale: log RMS² has the variance
  // (m4 − m2²)/(n m2²), estimated with n − 1 degrees of freedom and read
  // against Student's t. The log keeps the interval inside (0, ∞) and
  // skewed as RMS² is (at n = 5 the plain interval m2 ± z s covered 0.74
  // of normal and 0.82 of uniform outputs, this one 0.91 and 0.94;
  // docs/outputs.md, "RMS intervals").
  if (m2 == 0) return {0.0, 0.0};
  const double m4 = sum_r4 / nd;
  const double t = boost::math::quantile(boost::math::students_t(nd - 1), 1 - alpha / 2);
  const double log_half = t * std::sqrt(std::max(0.0, m4 - m2 * m2) / (nd - 1)) / m2;
  return {std::sqrt(m2 * std::exp(-log_half)), std::sqrt(m2 * std::exp(log_half))};
}

OutputStats::OutputStats(double shift, double scale)
    : shift_(shift),
      scale_(scale > 0 && std::isfinite(scale) ? scale : 1.0),
      inv_bin_width_(AbsHistogramLayout::kBins / (AbsHistogramLayout::kRange * scale_)),
      min_(std::numeric_limits<double>::infinity()),
      max_(-std::numeric_limits<double>::infinity()) {}

namespace {

constexpr auto kOverflowBin = static_cast<std::uint32_t>(AbsHistogramLayout::kBins);

/// The histogram bins of |v[i]| (the last bin: overflow and NaN).
struct ScalarBins {
  static void of(const double* v, std::size_t n, double inv_bin_width, std::uint32_t* bin) {
    for (std::size_t i = 0; i < n; ++i) {
      const double pos = std::abs(v[i]) * inv_bin_width;
      bin[i] = pos < static_cast<double>(kOverflowBin) ? static_cast<std::uint32_t>(pos) : kOverflowBin;
    }
  }
};

#if defined(__GNUC__) && defined(__x86_64__)
/// The same bins four at a time: minpd(pos, overflow) is the overflow bin
/// for pos at or above it and for a NaN pos (minpd returns its second
/// operand then), so the truncation sees only values in [0, kBins].
struct Avx2Bins {
  [[gnu::target("avx2")]] static void of(const double* v, std::size_t n, double inv_bin_width, std::uint32_t* bin) {
    const __m256d magnitude = _mm256_castsi256_pd(_mm256_set1_epi64x(0x7FFFFFFFFFFFFFFF));
    const __m256d scale = _mm256_set1_pd(inv_bin_width), top = _mm256_set1_pd(static_cast<double>(kOverflowBin));
    std::size_t i = 0;
    for (; i + 4 <= n; i += 4) {
      const __m256d pos = _mm256_mul_pd(_mm256_and_pd(_mm256_loadu_pd(v + i), magnitude), scale);
      _mm_storeu_si128(reinterpret_cast<__m128i*>(bin + i), _mm256_cvttpd_epi32(_mm256_min_pd(pos, top)));
    }
    ScalarBins::of(v + i, n - i, inv_bin_width, bin + i);
  }
};
#endif

/// One block's partial sums and extremes, in four fixed lanes.
struct BlockLanes {
  static constexpr std::size_t kLanes = 4;
  double sd[kLanes] = {}, sd2[kLanes] = {}, s2[kLanes] = {}, s4[kLanes] = {};
  double lo[kLanes], hi[kLanes];
};

// Four interleaved partial sums (fixed lanes, combined in a fixed order):
// the loop vectorises and the result is a pure function of the block; the
// AVX2 build of it below does the same operations on each lane in the same
// order (no reassociation, no fused multiply-add), so the same bits.
template <class Bins>
[[gnu::always_inline]] inline void block_lanes(const double* v, std::size_t n, double shift, double inv_bin_width,
                                               BlockLanes& b, std::uint64_t* hist) {
  constexpr std::size_t kLanes = BlockLanes::kLanes;
  // Local copies (registers): through `b` the compiler would have to assume
  // the stores may change v.
  double sd[kLanes] = {}, sd2[kLanes] = {}, s2[kLanes] = {}, s4[kLanes] = {}, lo[kLanes], hi[kLanes];
  for (std::size_t l = 0; l < kLanes; ++l) lo[l] = b.lo[l], hi[l] = b.hi[l];
  auto accumulate = [&](std::size_t l, double r) {
    const double d = r - shift, r2 = r * r;
    sd[l] += d;
    sd2[l] += d * d;
    s2[l] += r2;
    s4[l] += r2 * r2;
    lo[l] = std::min(lo[l], r);
    hi[l] = std::max(hi[l], r);
  };
  const std::size_t body = n - n % kLanes;
  for (std::size_t i = 0; i < body; i += kLanes)
    for (std::size_t l = 0; l < kLanes; ++l) accumulate(l, v[i + l]);
  for (std::size_t i = body; i < n; ++i) accumulate(i % kLanes, v[i]);  // the tail: lane i % kLanes
  for (std::size_t l = 0; l < kLanes; ++l)
    b.sd[l] = sd[l], b.sd2[l] = sd2[l], b.s2[l] = s2[l], b.s4[l] = s4[l], b.lo[l] = lo[l], b.hi[l] = hi[l];
  // The |r| histogram: the bins of a chunk first (vectorised where the CPU
  // can), then the counts.
  constexpr std::size_t kChunk = 256;
  std::uint32_t bin[kChunk];
  for (std::size_t start = 0; start < n; start += kChunk) {
    const std::size_t len = std::min(kChunk, n - start);
    Bins::of(v + start, len, inv_bin_width, bin);
    for (std::size_t i = 0; i < len; ++i) ++hist[bin[i]];
  }
}

using BlockLanesKernel = void (*)(const double*, std::size_t, double, double, BlockLanes&, std::uint64_t*);

void block_lanes_generic(const double* v, std::size_t n, double shift, double inv_bin_width, BlockLanes& b,
                         std::uint64_t* hist) {
  block_lanes<ScalarBins>(v, n, shift, inv_bin_width, b, hist);
}

#if defined(__GNUC__) && defined(__x86_64__)
[[gnu::target("avx2")]] void block_lanes_avx2(const double* v, std::size_t n, double shift, double inv_bin_width,
                                              BlockLanes& b, std::uint64_t* hist) {
  block_lanes<Avx2Bins>(v, n, shift, inv_bin_width, b, hist);
}
#endif

BlockLanesKernel best_block_lanes() {
#if defined(__GNUC__) && defined(__x86_64__)
  if (__builtin_cpu_supports("avx2")) return block_lanes_avx2;
#endif
  return block_lanes_generic;
}

}  // namespace

void OutputStats::add_block(const double* v, std::size_t n) {
  static const BlockLanesKernel kernel = best_block_lanes();
  constexpr auto kOverflow = static_cast<std::size_t>(AbsHistogramLayout::kBins);
  if (hist_.empty()) hist_.assign(kOverflow + 1, 0);
  BlockLanes b;
  std::fill(std::begin(b.lo), std::end(b.lo), min_);
  std::fill(std::begin(b.hi), std::end(b.hi), max_);
  kernel(v, n, shift_, inv_bin_width_, b, hist_.data());
  n_ += n;
  sum_d_.add((b.sd[0] + b.sd[1]) + (b.sd[2] + b.sd[3]));
  sum_d2_.add((b.sd2[0] + b.sd2[1]) + (b.sd2[2] + b.sd2[3]));
  sum_r2_.add((b.s2[0] + b.s2[1]) + (b.s2[2] + b.s2[3]));
  sum_r4_.add((b.s4[0] + b.s4[1]) + (b.s4[2] + b.s4[3]));
  min_ = std::min(std::min(b.lo[0], b.lo[1]), std::min(b.lo[2], b.lo[3]));
  max_ = std::max(std::max(b.hi[0], b.hi[1]), std::max(b.hi[2], b.hi[3]));
}

void OutputStats::merge(const OutputStats& o) {
  INSMC_ASSERT(o.shift_ == shift_ && o.scale_ == scale_, "merging stats of different outputs");
  n_ += o.n_;
  sum_d_.merge(o.sum_d_);
  sum_d2_.merge(o.sum_d2_);
  sum_r2_.merge(o.sum_r2_);
  sum_r4_.merge(o.sum_r4_);
  min_ = std::min(min_, o.min_);
  max_ = std::max(max_, o.max_);
  if (o.hist_.empty()) return;
  if (hist_.empty()) {
    hist_ = o.hist_;
    return;
  }
  for (std::size_t i = 0; i < hist_.size(); ++i) hist_[i] += o.hist_[i];
}

void OutputStats::merge(OutputStats&& o) {
  if (n_ == 0 && hist_.empty()) {  // nothing here yet: take the other's state whole
    INSMC_ASSERT(o.shift_ == shift_ && o.scale_ == scale_, "merging stats of different outputs");
    *this = std::move(o);
    return;
  }
  merge(static_cast<const OutputStats&>(o));
}

bool operator==(const OutputStats& a, const OutputStats& b) {
  const auto same_hist = [&] {
    if (a.hist_.size() == b.hist_.size()) return a.hist_ == b.hist_;
    const auto& full = a.hist_.empty() ? b.hist_ : a.hist_;  // an empty one is all zeros
    return std::all_of(full.begin(), full.end(), [](std::uint64_t c) { return c == 0; });
  };
  return a.shift_ == b.shift_ && a.scale_ == b.scale_ && a.inv_bin_width_ == b.inv_bin_width_ && a.n_ == b.n_ &&
         a.sum_d_ == b.sum_d_ && a.sum_d2_ == b.sum_d2_ && a.sum_r2_ == b.sum_r2_ && a.sum_r4_ == b.sum_r4_ &&
         a.min_ == b.min_ && a.max_ == b.max_ && same_hist();
}

OutputSummary OutputStats::summarize(double confidence, bool gaussian) const {
  OutputSummary s;
  s.n = n_;
  if (n_ == 0) {
    s.mean = s.std = s.rms = s.rms_lo = s.rms_hi = s.min = s.max = s.p95_abs = kNaN;
    return s;
  }
  const double nd = static_cast<double>(n_);
  const double d1 = sum_d_.value() / nd;
  s.mean = shift_ + d1;
  s.std = n_ > 1 ? std::sqrt(std::max(0.0, (sum_d2_.value() - nd * d1 * d1) / (nd - 1))) : kNaN;
  s.rms = std::sqrt(sum_r2_.value() / nd);
  const RmsBounds b = rms_confidence_interval(n_, sum_r2_.value(), sum_r4_.value(), confidence, gaussian);
  s.rms_lo = b.lo;
  s.rms_hi = b.hi;
  s.min = min_;
  s.max = max_;
  // p95 of |r|: the bin holding rank ceil(0.95 n), read at its upper edge.
  const std::uint64_t rank = static_cast<std::uint64_t>(std::ceil(0.95 * nd));
  std::uint64_t cum = 0;
  s.p95_is_upper_bound = true;
  s.p95_abs = std::max(std::abs(min_), std::abs(max_));
  for (int i = 0; i < AbsHistogramLayout::kBins && !hist_.empty(); ++i) {
    cum += hist_[i];
    if (cum >= rank) {
      s.p95_abs = std::min((i + 1) / inv_bin_width_, s.p95_abs);
      s.p95_is_upper_bound = false;
      break;
    }
  }
  return s;
}

void OutputStats::append_to(std::string& out) const {
  using byte_io::put_f64, byte_io::put_u32, byte_io::put_u64;
  put_f64(out, shift_);
  put_f64(out, scale_);
  put_u64(out, n_);
  sum_d_.append_to(out);
  sum_d2_.append_to(out);
  sum_r2_.append_to(out);
  sum_r4_.append_to(out);
  put_f64(out, min_);
  put_f64(out, max_);
  // The histogram's filled bins only, (u32 bin, u64 count) in increasing
  // bin order after their u32 number: the state follows the samples it
  // holds (a 2-sample study's checkpoint is a few hundred KB, not the
  // 33 KB × outputs of every bin written), and a full histogram costs at
  // most 1.5 times its dense size.
  std::uint32_t filled = 0;
  for (std::uint64_t c : hist_) filled += c != 0;
  put_u32(out, filled);
  for (std::size_t i = 0; i < hist_.size(); ++i)
    if (hist_[i] != 0) {
      put_u32(out, static_cast<std::uint32_t>(i));
      put_u64(out, hist_[i]);
    }
}

OutputStats OutputStats::read_from(std::string_view bytes, std::size_t& pos) {
  byte_io::Reader in(bytes, "OutputStats", pos);
  const double shift = in.f64(), scale = in.f64();
  OutputStats s(shift, scale);
  s.n_ = in.u64();
  pos = in.position();
  s.sum_d_ = ExactSum::read_from(bytes, pos);
  s.sum_d2_ = ExactSum::read_from(bytes, pos);
  s.sum_r2_ = ExactSum::read_from(bytes, pos);
  s.sum_r4_ = ExactSum::read_from(bytes, pos);
  byte_io::Reader tail(bytes, "OutputStats", pos);
  s.min_ = tail.f64();
  s.max_ = tail.f64();
  const std::uint32_t filled = tail.u32();
  if (filled > kOverflowBin + 1) tail.fail("more filled histogram bins than bins");
  // Allocated as add_block does, with the first value: an output without
  // any stays empty (all zeros).
  if (s.n_ > 0 || filled > 0) s.hist_.assign(AbsHistogramLayout::kBins + 1, 0);
  std::int64_t previous = -1;
  for (std::uint32_t k = 0; k < filled; ++k) {
    const std::uint32_t bin = tail.u32();
    if (bin > kOverflowBin || static_cast<std::int64_t>(bin) <= previous) tail.fail("histogram bins out of order");
    const std::uint64_t count = tail.u64();
    if (count == 0) tail.fail("an empty histogram bin listed as filled");
    s.hist_[bin] = count;
    previous = bin;
  }
  pos = tail.position();
  return s;
}

}  // namespace insmc::mc
