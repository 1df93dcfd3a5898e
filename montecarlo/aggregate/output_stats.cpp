#include "montecarlo/aggregate/output_stats.h"

#include <algorithm>
#include <boost/math/distributions/chi_squared.hpp>
#include <boost/math/distributions/normal.hpp>
#include <cmath>
#include <limits>

#include "lib/common/assert.h"
#include "montecarlo/aggregate/byte_io.h"

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
  // Delta method: Var(mean r²) = (m4 − m2²)/n; interval for RMS² then √.
  const double m4 = sum_r4 / nd;
  const double z = boost::math::quantile(boost::math::normal(), 1 - alpha / 2);
  const double half = z * std::sqrt(std::max(0.0, m4 - m2 * m2) / nd);
  return {std::sqrt(std::max(0.0, m2 - half)), std::sqrt(m2 + half)};
}

OutputStats::OutputStats(double shift, double scale)
    : shift_(shift),
      scale_(scale > 0 && std::isfinite(scale) ? scale : 1.0),
      inv_bin_width_(AbsHistogramLayout::kBins / (AbsHistogramLayout::kRange * scale_)),
      min_(std::numeric_limits<double>::infinity()),
      max_(-std::numeric_limits<double>::infinity()) {}

void OutputStats::add_block(const double* v, std::size_t n) {
  // Four interleaved partial sums (fixed lanes, combined in a fixed order):
  // the loop vectorises and the result is still a pure function of the block.
  constexpr std::size_t kLanes = 4;
  double sd[kLanes] = {}, sd2[kLanes] = {}, s2[kLanes] = {}, s4[kLanes] = {};
  double lo[kLanes] = {min_, min_, min_, min_}, hi[kLanes] = {max_, max_, max_, max_};
  auto accumulate = [&](std::size_t l, double r) {
    const double d = r - shift_, r2 = r * r;
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
  constexpr auto kOverflow = static_cast<std::size_t>(AbsHistogramLayout::kBins);
  if (hist_.empty()) hist_.assign(kOverflow + 1, 0);
  for (std::size_t i = 0; i < n; ++i) {
    const double pos = std::abs(v[i]) * inv_bin_width_;
    ++hist_[pos < static_cast<double>(kOverflow) ? static_cast<std::size_t>(pos) : kOverflow];
  }
  n_ += n;
  sum_d_.add((sd[0] + sd[1]) + (sd[2] + sd[3]));
  sum_d2_.add((sd2[0] + sd2[1]) + (sd2[2] + sd2[3]));
  sum_r2_.add((s2[0] + s2[1]) + (s2[2] + s2[3]));
  sum_r4_.add((s4[0] + s4[1]) + (s4[2] + s4[3]));
  min_ = std::min(std::min(lo[0], lo[1]), std::min(lo[2], lo[3]));
  max_ = std::max(std::max(hi[0], hi[1]), std::max(hi[2], hi[3]));
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
  using byte_io::put_f64, byte_io::put_u64;
  put_f64(out, shift_);
  put_f64(out, scale_);
  put_u64(out, n_);
  sum_d_.append_to(out);
  sum_d2_.append_to(out);
  sum_r2_.append_to(out);
  sum_r4_.append_to(out);
  put_f64(out, min_);
  put_f64(out, max_);
  if (hist_.empty()) {
    for (int i = 0; i <= AbsHistogramLayout::kBins; ++i) put_u64(out, 0);
  } else {
    for (std::uint64_t c : hist_) put_u64(out, c);
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
  s.hist_.assign(AbsHistogramLayout::kBins + 1, 0);
  for (auto& c : s.hist_) c = tail.u64();
  pos = tail.position();
  return s;
}

}  // namespace insmc::mc
