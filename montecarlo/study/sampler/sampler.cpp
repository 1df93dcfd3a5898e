#include "montecarlo/study/sampler/sampler.h"

#include <algorithm>
#include <vector>

namespace insmc::mc {

namespace {

// x[i] = (2 u[i] - 1) * scale[i] for i < len: the uniform transform of
// transform_one, the same three roundings in the same order (2u and 2u - 1
// are exact for u a multiple of 2^-53 in [0, 1), and a product of a
// difference cannot be contracted into an fma), so every kernel and the
// scalar formula agree bit for bit. (An fma(2u, b, -b) would round the same
// exact value once, but differs for b = +inf and in the sign of zero for
// b = 0, so it is not used.)
[[gnu::always_inline]] inline void uniform_span(const double* u, double* x, const double* scale,
                                                std::size_t len) {
  for (std::size_t i = 0; i < len; ++i) x[i] = (2.0 * u[i] - 1.0) * scale[i];
}

// All n samples: runs of `group` whole samples against the repeated scale
// (a fixed-length loop the compiler vectorises), then the last < group.
template <std::size_t kGroupLen>
[[gnu::always_inline]] inline void uniform_pass(const double* u, std::size_t n, double* x,
                                                const double* scale) {
  constexpr std::size_t kDim = uncertainty_slot::kDim;
  constexpr std::size_t kGroup = kGroupLen / kDim;
  std::size_t s = 0;
  for (; s + kGroup <= n; s += kGroup) uniform_span(u + s * kDim, x + s * kDim, scale, kGroupLen);
  uniform_span(u + s * kDim, x + s * kDim, scale, (n - s) * kDim);
}

using UniformPass = void (*)(const double*, std::size_t, double*, const double*);

template <std::size_t kGroupLen>
void uniform_pass_generic(const double* u, std::size_t n, double* x, const double* scale) {
  uniform_pass<kGroupLen>(u, n, x, scale);
}

#if defined(__GNUC__) && defined(__x86_64__)
template <std::size_t kGroupLen>
[[gnu::target("avx2")]] void uniform_pass_avx2(const double* u, std::size_t n, double* x,
                                               const double* scale) {
  uniform_pass<kGroupLen>(u, n, x, scale);
}
#endif

template <std::size_t kGroupLen>
UniformPass best_uniform_pass() {
#if defined(__GNUC__) && defined(__x86_64__)
  if (__builtin_cpu_supports("avx2")) return uniform_pass_avx2<kGroupLen>;
#endif
  return uniform_pass_generic<kGroupLen>;
}

}  // namespace

Sampler::Sampler(const UncertaintyModel& model) {
  for (int j = 0; j < uncertainty_slot::kDim; ++j) {
    const ParameterDistribution& p = model.at(j);
    kind_[j] = p.kind;
    bound_[j] = p.bound_si;
    fixed_[j] = p.fixed_si;
    if (p.kind == DistributionKind::kTruncatedNormal && p.bound_si > 0)
      normal_[j].emplace(p.bound_si / p.sigmas_in_bound, p.bound_si);
    if (p.kind == DistributionKind::kUniform) {
      for (int r = 0; r < kScaleSamples; ++r) uniform_scale_[r * uncertainty_slot::kDim + j] = p.bound_si;
    } else {
      other_[n_other_++] = j;
    }
  }
}

double Sampler::transform_one(int j, double u) const {
  switch (kind_[j]) {
    case DistributionKind::kUniform: return (2.0 * u - 1.0) * bound_[j];
    case DistributionKind::kTruncatedNormal:
      // The inverse CDF needs u in (0, 1): u is a multiple of 2^-53 in [0, 1).
      return normal_[j] ? (*normal_[j])(std::max(u, 0x1p-54)) : 0.0;
    case DistributionKind::kFixed: return fixed_[j];
    case DistributionKind::kZero: return 0.0;
  }
  return 0.0;
}

void Sampler::transform(const double* uniforms, std::size_t n, double* x) const {
  // Pass 1: every entry as if uniform (scale 0 for the other kinds, whose
  // entries pass 2 overwrites), in sample-major order.
  static const UniformPass pass = best_uniform_pass<kScaleSamples * uncertainty_slot::kDim>();
  if (n_other_ < uncertainty_slot::kDim) pass(uniforms, n, x, uniform_scale_.data());
  // Pass 2: the non-uniform parameters.
  if (n_other_ == 0) return;
  for (std::size_t s = 0; s < n; ++s) {
    const double* u = uniforms + s * uncertainty_slot::kDim;
    double* xs = x + s * uncertainty_slot::kDim;
    for (int k = 0; k < n_other_; ++k) xs[other_[k]] = transform_one(other_[k], u[other_[k]]);
  }
}

void Sampler::transform_draw_major(const double* uniforms, std::size_t n, double* x) const {
  for (int j = 0; j < uncertainty_slot::kDim; ++j) {
    const double* u = uniforms + static_cast<std::size_t>(j) * n;
    double* xj = x + static_cast<std::size_t>(j) * n;
    if (kind_[j] == DistributionKind::kUniform) {
      const double b = bound_[j];
      for (std::size_t s = 0; s < n; ++s) xj[s] = (2.0 * u[s] - 1.0) * b;  // transform_one's three roundings
    } else {
      for (std::size_t s = 0; s < n; ++s) xj[s] = transform_one(j, u[s]);
    }
  }
}

UncertaintyVector Sampler::draw(std::uint64_t seed, std::uint64_t index) const {
  std::vector<double> u(uncertainty_slot::kDim);
  fill_uniform01(seed, Stream::Uncertainties, index, uncertainty_slot::kDim, 1, u);
  UncertaintyVector x;
  transform_draw_major(u.data(), 1, x.data());  // one sample: both layouts are the same memory
  return x;
}

}  // namespace insmc::mc
