// accel_bias_instability: the accelerometer bias wanders (Gauss–Markov or
// random walk) instead of being constant over a run.
#include "lib/truth/effects/effects.h"

namespace insmc::effects {
namespace {

constexpr EffectParameter kParameters[] = {
    {"sigma", Dimension::kAcceleration, 50e-6 * kGravityMps2,
     "1σ of the bias (Gauss–Markov) or its 1σ after one hour (random walk, tau = 0)",
     ParameterRange::kNonNegative, 0.0, EffectMagnitude::kScaled, RawSensorLimit::kBiasWander},
    {"tau", Dimension::kTime, 300.0, "correlation time; 0 selects a random walk",
     ParameterRange::kNonNegative},
};

void realize(const EffectSpec& spec, const EffectContext& c, NormalDraws& draws, Perturbations& p) {
  const GridProcess bias =
      make_gauss_markov(spec.value("sigma"), spec.value("tau"), c.duration_s, c.noise_grid_s, draws);
  // The leveling loops null the bias present at switch-over like δf.
  p.alignment_bias_mps2 += bias.at(0.0);
  p.bias_process.add(bias);
}

}  // namespace

const EffectDefinition& accel_bias_instability() {
  static const EffectDefinition d{
      {"accel_bias_instability",
       "accelerometer bias instability: a first-order Gauss–Markov process of correlation time "
       "tau, or a random walk (tau = 0), per axis",
       kParameters, true, RawSensor::kAccelerometer},
      &realize};
  return d;
}

}  // namespace insmc::effects
