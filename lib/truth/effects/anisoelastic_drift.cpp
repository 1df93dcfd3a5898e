// anisoelastic_drift: g²-sensitive gyro drift from unequal compliance of
// the gyro rotor support, proportional to products of specific-force
// components; zero on a level platform, growing as the earth turns the
// gravity vector in the space-stabilized platform.
#include "lib/truth/effects/effects.h"

namespace insmc::effects {
namespace {

constexpr EffectParameter kParameters[] = {
    {"coefficient", Dimension::kAngularRate, 5.0 * kMeruToRadps,
     "drift per g² of the product of the two other specific-force components (per 1 g = "
     "9.80665 m/s²)",
     ParameterRange::kAny, 0.0, EffectMagnitude::kScaled},
};

void realize(const EffectSpec& spec, const EffectContext&, NormalDraws&, Perturbations& p) {
  p.anisoelastic_radps_per_mps2sq += spec.value("coefficient") / (kGravityMps2 * kGravityMps2);
}

}  // namespace

const EffectDefinition& anisoelastic_drift() {
  static const EffectDefinition d{
      {"anisoelastic_drift",
       "anisoelastic (g²-sensitive) gyro drift: ω_x = c f_y f_z, ω_y = c f_z f_x, "
       "ω_z = c f_x f_y in the platform frame",
       kParameters, false, RawSensor::kGyro},
      &realize};
  return d;
}

}  // namespace insmc::effects
