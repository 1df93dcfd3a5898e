#pragma once
/// Draws the uncertainty vector of each sample from the study's
/// UncertaintyModel. Every parameter uses exactly one uniform of the
/// `Uncertainties` stream (draw j for parameter j), so sample i's x is a
/// pure function of (seed, i) and a block of samples is drawn in bulk.
#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>

#include "lib/uncertainty/uncertainty_model.h"
#include "montecarlo/study/random/philox.h"

namespace insmc::mc {

class Sampler {
 public:
  explicit Sampler(const UncertaintyModel& model);

  /// uniforms: n × kDim, sample-major (fill_uniform01 layout);
  /// x: kDim × n, column-major (one column per sample). Bit for bit
  /// x[s * kDim + j] == transform_one(j, uniforms[s * kDim + j]). The
  /// uniform parameters go through one vectorised pass (AVX2 when the CPU
  /// has it); the other kinds are then written parameter by parameter.
  /// uniforms and x must not overlap.
  void transform(const double* uniforms, std::size_t n, double* x) const;

  /// The same draws in draw-major order (fill_uniform01_draw_major's
  /// layout): x[j * n + s] == transform_one(j, uniforms[j * n + s]), bit for
  /// bit. uniforms and x must not overlap.
  void transform_draw_major(const double* uniforms, std::size_t n, double* x) const;

  /// The uncertainty vector of sample `index` alone (for --replay).
  UncertaintyVector draw(std::uint64_t seed, std::uint64_t index) const;

  /// Catalogue parameter j's draw from one uniform u in [0, 1) (also used
  /// for the per-alignment redraws of a realignment).
  double transform_one(int j, double u) const;

 private:
  std::array<DistributionKind, uncertainty_slot::kDim> kind_;
  std::array<double, uncertainty_slot::kDim> bound_, fixed_;
  std::array<std::optional<TruncatedNormalTransform>, uncertainty_slot::kDim> normal_;
  /// bound_[j] for uniform parameters, 0 for the others, repeated for
  /// kScaleSamples samples so a run of whole samples is one flat loop.
  static constexpr int kScaleSamples = 4;
  std::array<double, kScaleSamples * uncertainty_slot::kDim> uniform_scale_{};
  /// The parameters that are not uniform, in increasing order.
  std::array<int, uncertainty_slot::kDim> other_{};
  int n_other_ = 0;
};

}  // namespace insmc::mc
