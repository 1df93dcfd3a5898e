// velocity_random_walk: white noise on the accelerometer outputs.
#include "lib/truth/effects/effects.h"

namespace insmc::effects {
namespace {

constexpr EffectParameter kParameters[] = {
    {"velocity_1h", Dimension::kVelocity, 0.3,
     "1σ velocity error after one hour per axis (VRW coefficient × sqrt(1 h))",
     ParameterRange::kNonNegative, 0.0, EffectMagnitude::kScaled, RawSensorLimit::kWhiteNoise1h},
};

void realize(const EffectSpec& spec, const EffectContext& c, NormalDraws& draws, Perturbations& p) {
  p.velocity_walk.add(
      make_random_walk(spec.value("velocity_1h"), c.duration_s, c.noise_grid_s, draws));
}

}  // namespace

const EffectDefinition& velocity_random_walk() {
  static const EffectDefinition d{
      {"velocity_random_walk",
       "accelerometer velocity random walk: white noise on the specific force, so the velocity "
       "increments perform a random walk",
       kParameters, true, RawSensor::kAccelerometer},
      &realize};
  return d;
}

}  // namespace insmc::effects
