#pragma once
/// One definition per named effect (one file each in this folder): the
/// registry entry and the function realizing it into a Perturbations.
#include "lib/truth/effect.h"
#include "lib/units/units.h"

namespace insmc::effects {

/// Adds the effect's contribution to `p`. `draws` is the effect's own stream
/// (used only by random effects).
using RealizeFn = void (*)(const EffectSpec& spec, const EffectContext& context, NormalDraws& draws,
                           Perturbations& p);

struct EffectDefinition {
  EffectInfo info;
  RealizeFn realize;
};

const EffectDefinition& quantization();
const EffectDefinition& sway();
const EffectDefinition& accel_bias_instability();
const EffectDefinition& gyro_drift_instability();
const EffectDefinition& angle_random_walk();
const EffectDefinition& velocity_random_walk();
const EffectDefinition& thermal_transient();
const EffectDefinition& anisoelastic_drift();
const EffectDefinition& scale_factor_nonlinearity();
const EffectDefinition& gravity_model();
const EffectDefinition& deflection_of_vertical();
const EffectDefinition& alignment_transient();
const EffectDefinition& switch_transient();

/// Three independent standard normal draws, in x, y, z order.
inline Vec3 normal3(NormalDraws& draws) {
  const double a = draws.next(), b = draws.next(), c = draws.next();
  return Vec3(a, b, c);
}

}  // namespace insmc::effects
