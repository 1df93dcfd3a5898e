// angle_random_walk: white noise on the gyro rates, so the platform angle
// performs a random walk.
#include "lib/truth/effects/effects.h"

namespace insmc::effects {
namespace {

constexpr EffectParameter kParameters[] = {
    {"angle_1h", Dimension::kAngle, 0.1 * kMradToRad,
     "1σ platform angle after one hour per axis (ARW coefficient × sqrt(1 h))",
     ParameterRange::kNonNegative, 0.0, EffectMagnitude::kScaled, RawSensorLimit::kWhiteNoise1h},
};

void realize(const EffectSpec& spec, const EffectContext& c, NormalDraws& draws, Perturbations& p) {
  p.angle_walk.add(make_random_walk(spec.value("angle_1h"), c.duration_s, c.noise_grid_s, draws));
}

}  // namespace

const EffectDefinition& angle_random_walk() {
  static const EffectDefinition d{
      {"angle_random_walk",
       "gyro angle random walk: white rate noise turns the platform by a random walk, seen by the "
       "accelerometers as a wandering tilt",
       kParameters, true, RawSensor::kGyro},
      &realize};
  return d;
}

}  // namespace insmc::effects
