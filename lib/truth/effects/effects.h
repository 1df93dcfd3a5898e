#pragma once
/// One definition per named effect (one file each in this folder, listed
/// once in effect_list.h): the registry entry and the function realizing it
/// into a Perturbations.
#include "lib/truth/effect.h"
#include "lib/units/units.h"

namespace insmc::effects {

#define INSMC_EFFECT(name) const EffectDefinition& name();
#include "lib/truth/effects/effect_list.h"
#undef INSMC_EFFECT

/// Three independent standard normal draws, in x, y, z order.
inline Vec3 normal3(NormalDraws& draws) {
  const double a = draws.next(), b = draws.next(), c = draws.next();
  return Vec3(a, b, c);
}

}  // namespace insmc::effects
