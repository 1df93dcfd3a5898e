#include "montecarlo/aggregate/moments.h"

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
constexpr std::uint32_t kFormatTag = 0x31304D53u;  // "SM01" little-endian

}  // namespace

void ScalarMoments::add(double r) {
  INSMC_ASSERT(std::isfinite(r), "ScalarMoments::add: non-finite value {}", r);
  if (n_ == 0) {
    min_ = r;
    max_ = r;
  } else {
    min_ = std::min(min_, r);
    max_ = std::max(max_, r);
  }
  ++n_;
  // Welford (1962): mean and M2 updated with the deviation from the old mean.
  const double delta = r - mean_;
  mean_ += delta / static_cast<double>(n_);
  m2_ += delta * (r - mean_);
  const double r2 = r * r;
  sum_r2_ += r2;
  sum_r4_ += r2 * r2;
}

void ScalarMoments::merge(const ScalarMoments& other) {
  if (other.n_ == 0) return;
  if (n_ == 0) {
    *this = other;
    return;
  }
  // Chan, Golub & LeVeque (1979), pairwise update:
  //   mean = mean_a + delta n_b / n,  M2 = M2_a + M2_b + delta^2 n_a n_b / n.
  const double na = static_cast<double>(n_);
  const double nb = static_cast<double>(other.n_);
  const double n = na + nb;
  const double delta = other.mean_ - mean_;
  mean_ += delta * (nb / n);
  m2_ += other.m2_ + delta * delta * (na * nb / n);
  n_ += other.n_;
  sum_r2_ += other.sum_r2_;
  sum_r4_ += other.sum_r4_;
  min_ = std::min(min_, other.min_);
  max_ = std::max(max_, other.max_);
}

double ScalarMoments::mean() const { return n_ == 0 ? kNaN : mean_; }

double ScalarMoments::stddev() const {
  return n_ < 2 ? kNaN : std::sqrt(m2_ / static_cast<double>(n_ - 1));
}

double ScalarMoments::rms() const {
  return n_ == 0 ? kNaN : std::sqrt(sum_r2_ / static_cast<double>(n_));
}

double ScalarMoments::min() const { return n_ == 0 ? kNaN : min_; }
double ScalarMoments::max() const { return n_ == 0 ? kNaN : max_; }

RmsInterval ScalarMoments::rms_interval(double confidence, IntervalMethod method) const {
  INSMC_ASSERT(confidence > 0.0 && confidence < 1.0,
               "rms_interval: confidence = {} outside (0, 1)", confidence);
  if (n_ < 2) return {kNaN, kNaN};
  const double alpha = 1.0 - confidence;
  const double n = static_cast<double>(n_);
  const double m2 = sum_r2_ / n;
  switch (method) {
    case IntervalMethod::DeltaFourthMoment: {
      const double m4 = sum_r4_ / n;
      const double var_m2 = std::max(0.0, (m4 - m2 * m2) / n);
      const boost::math::normal_distribution<double> normal(0.0, 1.0);
      const double z = boost::math::quantile(boost::math::complement(normal, alpha / 2));
      const double half = z * std::sqrt(var_m2);
      return {std::sqrt(std::max(0.0, m2 - half)), std::sqrt(m2 + half)};
    }
    case IntervalMethod::ChiSquareGaussian: {
      if (m2 == 0.0) return {0.0, 0.0};
      const boost::math::chi_squared_distribution<double> chi2(n);
      const double upper_q = boost::math::quantile(boost::math::complement(chi2, alpha / 2));
      const double lower_q = boost::math::quantile(chi2, alpha / 2);
      return {std::sqrt(n * m2 / upper_q), std::sqrt(n * m2 / lower_q)};
    }
  }
  INSMC_ASSERT(false, "rms_interval: unknown method {}", static_cast<int>(method));
  return {kNaN, kNaN};
}

std::string ScalarMoments::serialize() const {
  std::string out;
  out.reserve(4 + 7 * 8);
  byte_io::put_u32(out, kFormatTag);
  byte_io::put_u64(out, n_);
  byte_io::put_f64(out, mean_);
  byte_io::put_f64(out, m2_);
  byte_io::put_f64(out, sum_r2_);
  byte_io::put_f64(out, sum_r4_);
  byte_io::put_f64(out, min_);
  byte_io::put_f64(out, max_);
  return out;
}

ScalarMoments ScalarMoments::deserialize(std::string_view bytes) {
  byte_io::Reader in(bytes, "ScalarMoments");
  if (in.u32() != kFormatTag) in.fail("bad format tag");
  ScalarMoments m;
  m.n_ = in.u64();
  m.mean_ = in.f64();
  m.m2_ = in.f64();
  m.sum_r2_ = in.f64();
  m.sum_r4_ = in.f64();
  m.min_ = in.f64();
  m.max_ = in.f64();
  in.expect_end();
  return m;
}

}  // namespace insmc::mc
