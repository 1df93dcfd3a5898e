#pragma once
/// Randomness for the truth simulator's effects, without depending on
/// montecarlo/ (lib/ must not): the caller passes a counter-based standard
/// normal source, a pure function of (stream, counter). The Monte Carlo engine
/// wraps its Philox stream (purpose TruthEffects, keyed by the sample index);
/// tests and tools may use hashed_normal_source below. Each effect instance
/// draws from its own stream (effect_stream()), so switching one effect on
/// leaves the draws of the others unchanged.
#include <cstdint>
#include <functional>

namespace insmc {

/// z ~ N(0, 1) as a pure function of (stream, counter).
using NormalSource = std::function<double(std::uint64_t stream, std::uint64_t counter)>;

/// A simple, deterministic NormalSource: splitmix64 of (seed, stream,
/// counter) to two 53-bit uniforms, Box–Muller (cosine branch). Written by
/// hand (no std:: distributions), so bit-identical on every platform with an
/// IEEE libm. Adequate for tests and tools; the Monte Carlo engine uses
/// Philox.
double hashed_standard_normal(std::uint64_t seed, std::uint64_t stream, std::uint64_t counter);

inline NormalSource hashed_normal_source(std::uint64_t seed) {
  return [seed](std::uint64_t stream, std::uint64_t counter) {
    return hashed_standard_normal(seed, stream, counter);
  };
}

/// Sequential draws from one stream of a NormalSource.
class NormalDraws {
 public:
  NormalDraws(const NormalSource& source, std::uint64_t stream) : source_(&source), stream_(stream) {}
  double next() { return (*source_)(stream_, counter_++); }
  /// Uniform in (0, 1) from a normal draw, Φ(z) (for phases and frequencies).
  double next_uniform();

 private:
  const NormalSource* source_;
  std::uint64_t stream_;
  std::uint64_t counter_ = 0;
};

}  // namespace insmc
