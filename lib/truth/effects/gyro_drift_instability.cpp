// gyro_drift_instability: the gyro drift wanders (Gauss–Markov or random
// walk) instead of being constant over a run.
#include "lib/truth/effects/effects.h"

namespace insmc::effects {
namespace {

constexpr EffectParameter kParameters[] = {
    {"sigma", Dimension::kAngularRate, 1.0 * kMeruToRadps,
     "1σ of the drift (Gauss–Markov) or its 1σ after one hour (random walk, tau = 0)",
     ParameterRange::kNonNegative, 0.0, EffectMagnitude::kScaled, RawSensorLimit::kBiasWander},
    {"tau", Dimension::kTime, 1200.0, "correlation time; 0 selects a random walk",
     ParameterRange::kNonNegative},
};

void realize(const EffectSpec& spec, const EffectContext& c, NormalDraws& draws, Perturbations& p) {
  const GridProcess drift =
      make_gauss_markov(spec.value("sigma"), spec.value("tau"), c.duration_s, c.noise_grid_s, draws);
  // The alignment sees the drift at switch-over like ω_do.
  p.alignment_drift_radps += drift.at(0.0);
  p.drift_process.add(drift);
}

}  // namespace

const EffectDefinition& gyro_drift_instability() {
  static const EffectDefinition d{
      {"gyro_drift_instability",
       "gyro drift instability: a first-order Gauss–Markov process of correlation time tau, or a "
       "random walk (rate random walk, tau = 0), per gyro",
       kParameters, true, RawSensor::kGyro},
      &realize};
  return d;
}

}  // namespace insmc::effects
