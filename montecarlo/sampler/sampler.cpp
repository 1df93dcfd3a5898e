#include "montecarlo/sampler/sampler.h"

#include <algorithm>
#include <vector>

namespace insmc::mc {

Sampler::Sampler(const UncertaintyModel& model) {
  for (int j = 0; j < ux::kDim; ++j) {
    const ParameterDistribution& p = model.at(j);
    kind_[j] = p.kind;
    bound_[j] = p.bound_si;
    fixed_[j] = p.fixed_si;
    if (p.kind == DistributionKind::kTruncatedNormal && p.bound_si > 0)
      normal_[j].emplace(p.bound_si / p.sigmas_in_bound, p.bound_si);
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
  for (std::size_t s = 0; s < n; ++s)
    for (int j = 0; j < ux::kDim; ++j) x[s * ux::kDim + j] = transform_one(j, uniforms[s * ux::kDim + j]);
}

UncertaintyVector Sampler::draw(std::uint64_t seed, std::uint64_t index) const {
  std::vector<double> u(ux::kDim);
  fill_uniform01(seed, Stream::Uncertainties, index, ux::kDim, 1, u);
  UncertaintyVector x;
  transform(u.data(), 1, x.data());
  return x;
}

}  // namespace insmc::mc
