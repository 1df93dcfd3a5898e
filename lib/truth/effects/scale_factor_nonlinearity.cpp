// scale_factor_nonlinearity: the accelerometer output has a term quadratic
// in the specific force along its axis.
#include "lib/truth/effects/effects.h"

namespace insmc::effects {
namespace {

constexpr EffectParameter kParameters[] = {
    {"k2", Dimension::kAcceleration, 200e-6 * kGravityMps2,
     "output error at 1 g along the axis (second-order coefficient × 1 g²), all axes",
     ParameterRange::kAny, 0.0, EffectMagnitude::kScaled},
};

void realize(const EffectSpec& spec, const EffectContext&, NormalDraws&, Perturbations& p) {
  p.accel_quadratic_per_mps2 += Vec3::Constant(spec.value("k2") / (kGravityMps2 * kGravityMps2));
}

}  // namespace

const EffectDefinition& scale_factor_nonlinearity() {
  static const EffectDefinition d{
      {"scale_factor_nonlinearity",
       "accelerometer scale-factor nonlinearity: f_m,k += k2 (f_k / 1 g)²",
       kParameters, false, RawSensor::kAccelerometer},
      &realize};
  return d;
}

}  // namespace insmc::effects
