#include "montecarlo/random/philox.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "lib/common/assert.h"

namespace insmc::mc {

double normal_cdf(double x) { return 0.5 * std::erfc(-x / std::numbers::sqrt2); }

double inverse_normal_cdf(double p) {
  // Wichura, AS 241 PPND16 (Appl. Statist. 37 (1988) 477-484). Coefficients
  // as published; the same values appear in R's qnorm.c.
  INSMC_ASSERT(p >= 0.0 && p <= 1.0, "inverse_normal_cdf: p = {} outside [0, 1]", p);
  if (p == 0.0) return -std::numeric_limits<double>::infinity();
  if (p == 1.0) return std::numeric_limits<double>::infinity();

  const double q = p - 0.5;
  if (std::fabs(q) <= 0.425) {
    // Central region, |q| <= 0.425: r = 0.180625 - q^2.
    const double r = 0.180625 - q * q;
    const double num =
        (((((((2.5090809287301226727e+3 * r + 3.3430575583588128105e+4) * r +
              6.7265770927008700853e+4) * r + 4.5921953931549871457e+4) * r +
            1.3731693765509461125e+4) * r + 1.9715909503065514427e+3) * r +
          1.3314166789178437745e+2) * r + 3.3871328727963666080e+0);
    const double den =
        (((((((5.2264952788528545610e+3 * r + 2.8729085735721942674e+4) * r +
              3.9307895800092710610e+4) * r + 2.1213794301586595867e+4) * r +
            5.3941960214247511077e+3) * r + 6.8718700749205790830e+2) * r +
          4.2313330701600911252e+1) * r + 1.0);
    return q * num / den;
  }

  // Tails: r = sqrt(-log(min(p, 1 - p))); 1 - p is exact for p >= 0.5.
  double r = std::sqrt(-std::log(q < 0.0 ? p : 1.0 - p));
  double val = 0.0;
  if (r <= 5.0) {
    // min(p, 1 - p) >= exp(-25) ~ 1.4e-11.
    r -= 1.6;
    const double num =
        (((((((7.74545014278341407640e-4 * r + 2.27238449892691845833e-2) * r +
              2.41780725177450611770e-1) * r + 1.27045825245236838258e+0) * r +
            3.64784832476320460504e+0) * r + 5.76949722146069140550e+0) * r +
          4.63033784615654529590e+0) * r + 1.42343711074968357734e+0);
    const double den =
        (((((((1.05075007164441684324e-9 * r + 5.47593808499534494600e-4) * r +
              1.51986665636164571966e-2) * r + 1.48103976427480074590e-1) * r +
            6.89767334985100004550e-1) * r + 1.67638483018380384940e+0) * r +
          2.05319162663775882187e+0) * r + 1.0);
    val = num / den;
  } else {
    // Far tails.
    r -= 5.0;
    const double num =
        (((((((2.01033439929228813265e-7 * r + 2.71155556874348757815e-5) * r +
              1.24266094738807843860e-3) * r + 2.65321895265761230930e-2) * r +
            2.96560571828504891230e-1) * r + 1.78482653991729133580e+0) * r +
          5.46378491116411436990e+0) * r + 6.65790464350110377720e+0);
    const double den =
        (((((((2.04426310338993978564e-15 * r + 1.42151175831644588870e-7) * r +
              1.84631831751005468180e-5) * r + 7.86869131145613259100e-4) * r +
            1.48753612908506148525e-2) * r + 1.36929880922735805310e-1) * r +
          5.99832206555887937690e-1) * r + 1.0);
    val = num / den;
  }
  return q < 0.0 ? -val : val;
}

TruncatedNormalTransform::TruncatedNormalTransform(double sigma, double bound)
    : sigma_(sigma), bound_(bound), p_lo_(0.0), width_(1.0) {
  INSMC_ASSERT(sigma >= 0.0 && bound >= 0.0,
               "truncated normal: sigma = {}, bound = {}; both must be >= 0", sigma, bound);
  if (sigma > 0.0 && bound > 0.0) {
    const double c = bound / sigma;  // dimensionless half-width in sigmas
    p_lo_ = 0.5 * std::erfc(c / std::numbers::sqrt2);
    width_ = std::erf(c / std::numbers::sqrt2);
  }
}

double TruncatedNormalTransform::operator()(double u_open) const {
  if (sigma_ == 0.0 || bound_ == 0.0) return 0.0;
  // Invert in the lower tail for both halves: T(1 - u) = -T(u) exactly.
  const bool upper = u_open >= 0.5;
  const double u_lower = upper ? 1.0 - u_open : u_open;
  const double z = inverse_normal_cdf(p_lo_ + u_lower * width_);
  const double x = std::clamp(sigma_ * z, -bound_, bound_);
  return upper ? -x : x;
}

CounterStream::CounterStream(std::uint64_t seed, Stream purpose, std::uint64_t sample_index)
    : key_(philox_key(seed)), counter_(philox_counter(sample_index, purpose, 0)) {}

void CounterStream::refill() {
  INSMC_ASSERT(next_block_ <= std::numeric_limits<std::uint32_t>::max(),
               "CounterStream: more than 2^34 words drawn from one stream");
  counter_[3] = static_cast<std::uint32_t>(next_block_);
  buffer_ = philox4x32_10(counter_, key_);
  ++next_block_;
  word_ = 0;
}

void CounterStream::seek(std::uint64_t position) {
  next_block_ = position / 4;
  const int word = static_cast<int>(position % 4);
  if (word == 0) {
    word_ = 4;  // generate lazily on the next draw
  } else {
    refill();
    word_ = word;
  }
}

namespace {

// Number of counters processed together by the bulk kernels.
constexpr std::size_t kLanes = 16;

struct LaneBlock {
  alignas(64) std::uint32_t w0[kLanes];
  alignas(64) std::uint32_t w1[kLanes];
  alignas(64) std::uint32_t w2[kLanes];
  alignas(64) std::uint32_t w3[kLanes];
};

// Ten Philox rounds on kLanes counters at once; same arithmetic as
// philox4x32_10, lane by lane. The high and low halves of each product are
// separate expressions (a 32x32->64 multiply shifted down, and a wrapping
// 32-bit multiply): in this form GCC 12 vectorises the lane loop, which it
// does not when one 64-bit product is split into both halves.
[[gnu::always_inline]] inline void philox_lanes_body(LaneBlock& b, PhiloxKey key) {
  for (int round = 0; round < kPhiloxRounds; ++round) {
    if (round > 0) {
      key.k0 += kPhiloxW0;
      key.k1 += kPhiloxW1;
    }
    for (std::size_t l = 0; l < kLanes; ++l) {
      const std::uint32_t a = b.w0[l];
      const std::uint32_t c = b.w2[l];
      const auto hi0 = static_cast<std::uint32_t>((std::uint64_t{kPhiloxM0} * a) >> 32);
      const std::uint32_t lo0 = kPhiloxM0 * a;
      const auto hi1 = static_cast<std::uint32_t>((std::uint64_t{kPhiloxM1} * c) >> 32);
      const std::uint32_t lo1 = kPhiloxM1 * c;
      const std::uint32_t n0 = hi1 ^ b.w1[l] ^ key.k0;
      const std::uint32_t n2 = hi0 ^ b.w3[l] ^ key.k1;
      b.w0[l] = n0;
      b.w1[l] = lo1;
      b.w2[l] = n2;
      b.w3[l] = lo0;
    }
  }
}

// Baseline kernel: one scalar block function per lane. Measured on x86-64
// with GCC 12, SSE2 vectorisation of the lane loop is *slower* than scalar
// code (the 32x32->64 multiplies need shuffles around pmuludq), so the
// portable path stays scalar and relies on instruction-level parallelism.
void philox_lanes_generic(LaneBlock& b, PhiloxKey key) {
  for (std::size_t l = 0; l < kLanes; ++l) {
    const PhiloxBlock out = philox4x32_10({b.w0[l], b.w1[l], b.w2[l], b.w3[l]}, key);
    b.w0[l] = out[0];
    b.w1[l] = out[1];
    b.w2[l] = out[2];
    b.w3[l] = out[3];
  }
}

#if defined(__GNUC__) && defined(__x86_64__)
#define INSMC_PHILOX_HAVE_AVX2_KERNEL 1
// AVX2 kernel (vpmuludq on 8 lanes), chosen at run time when the CPU has it.
// Integer arithmetic only, so its bits equal the generic kernel's.
[[gnu::target("avx2")]] void philox_lanes_avx2(LaneBlock& b, PhiloxKey key) {
  philox_lanes_body(b, key);
}
#endif

using LaneKernel = void (*)(LaneBlock&, PhiloxKey);

LaneKernel lane_kernel(detail::PhiloxKernel kernel) {
  switch (kernel) {
    case detail::PhiloxKernel::Generic:
      return philox_lanes_generic;
    case detail::PhiloxKernel::Avx2:
#ifdef INSMC_PHILOX_HAVE_AVX2_KERNEL
      return philox_lanes_avx2;
#else
      break;
#endif
  }
  INSMC_ASSERT(false, "Philox kernel {} not available", static_cast<int>(kernel));
  return philox_lanes_generic;
}

}  // namespace

namespace detail {

bool kernel_available(PhiloxKernel kernel) {
  switch (kernel) {
    case PhiloxKernel::Generic:
      return true;
    case PhiloxKernel::Avx2:
#ifdef INSMC_PHILOX_HAVE_AVX2_KERNEL
      return __builtin_cpu_supports("avx2");
#else
      return false;
#endif
  }
  return false;
}

PhiloxKernel best_kernel() {
  static const PhiloxKernel best =
      kernel_available(PhiloxKernel::Avx2) ? PhiloxKernel::Avx2 : PhiloxKernel::Generic;
  return best;
}

void fill_uniform01_with(PhiloxKernel kernel, std::uint64_t seed, Stream purpose,
                         std::uint64_t first_index, std::size_t count_per_sample,
                         std::size_t n_samples, std::span<double> out) {
  INSMC_ASSERT(out.size() == count_per_sample * n_samples,
               "fill_uniform01: out.size() = {}, expected {} x {}", out.size(), count_per_sample,
               n_samples);
  if (count_per_sample == 0 || n_samples == 0) return;
  const LaneKernel run = lane_kernel(kernel);
  // Each block yields two uniforms (words 0,1 and words 2,3); with an odd
  // count the last block of each sample yields one.
  const std::size_t blocks_per_sample = (count_per_sample + 1) / 2;
  INSMC_ASSERT(blocks_per_sample - 1 <= std::numeric_limits<std::uint32_t>::max(),
               "fill_uniform01: {} uniforms per sample exceed one stream", count_per_sample);
  const bool odd = count_per_sample % 2 != 0;
  const PhiloxKey key = philox_key(seed);
  const auto purpose_word = static_cast<std::uint32_t>(purpose);
  const std::size_t total_blocks = blocks_per_sample * n_samples;

  // Blocks are enumerated sample by sample, block by block, which is also
  // the order of their uniforms in `out`, so the output is written
  // sequentially.
  std::uint64_t index = first_index;
  std::size_t block = 0;
  double* dst = out.data();
  LaneBlock b;
  bool single[kLanes];  // lane yields one uniform (last block, odd count)
  for (std::size_t start = 0; start < total_blocks; start += kLanes) {
    const std::size_t lanes = std::min(kLanes, total_blocks - start);
    for (std::size_t l = 0; l < lanes; ++l) {
      b.w0[l] = static_cast<std::uint32_t>(index);
      b.w1[l] = static_cast<std::uint32_t>(index >> 32);
      b.w2[l] = purpose_word;
      b.w3[l] = static_cast<std::uint32_t>(block);
      single[l] = odd && block + 1 == blocks_per_sample;
      if (++block == blocks_per_sample) {
        block = 0;
        ++index;
      }
    }
    for (std::size_t l = lanes; l < kLanes; ++l) {  // unused tail lanes
      b.w0[l] = b.w1[l] = b.w2[l] = b.w3[l] = 0;
    }
    run(b, key);
    for (std::size_t l = 0; l < lanes; ++l) {
      *dst++ = uniform01_from_words(b.w0[l], b.w1[l]);
      if (!single[l]) *dst++ = uniform01_from_words(b.w2[l], b.w3[l]);
    }
  }
  INSMC_ASSERT(dst == out.data() + out.size(), "fill_uniform01: wrote {} of {} values",
               dst - out.data(), out.size());
}

}  // namespace detail

void fill_uniform01(std::uint64_t seed, Stream purpose, std::uint64_t first_index,
                    std::size_t count_per_sample, std::size_t n_samples, std::span<double> out) {
  detail::fill_uniform01_with(detail::best_kernel(), seed, purpose, first_index, count_per_sample,
                              n_samples, out);
}

}  // namespace insmc::mc
