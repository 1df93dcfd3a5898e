#pragma once
/// Draws the uncertainty vector of each sample from the study's
/// UncertaintyModel. Every parameter uses exactly one uniform of the
/// `Uncertainties` stream (draw j for parameter j), so sample i's x is a
/// pure function of (seed, i) and a block of samples is drawn in bulk.
#include <array>
#include <optional>
#include <cstdint>

#include "lib/uncertainty/uncertainty_model.h"
#include "montecarlo/random/philox.h"

namespace insmc::mc {

class Sampler {
 public:
  explicit Sampler(const UncertaintyModel& model);

  /// uniforms: n × kDim, sample-major (fill_uniform01 layout);
  /// x: kDim × n, column-major (one column per sample).
  void transform(const double* uniforms, std::size_t n, double* x) const;

  /// The uncertainty vector of sample `index` alone (for --replay).
  UncertaintyVector draw(std::uint64_t seed, std::uint64_t index) const;

  /// Catalogue parameter j's draw from one uniform u in [0, 1) (also used
  /// for the per-alignment redraws of a realignment).
  double transform_one(int j, double u) const;

 private:
  std::array<DistributionKind, ux::kDim> kind_;
  std::array<double, ux::kDim> bound_, fixed_;
  std::array<std::optional<TruncatedNormalTransform>, ux::kDim> normal_;
};

}  // namespace insmc::mc
