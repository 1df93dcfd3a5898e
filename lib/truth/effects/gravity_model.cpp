// gravity_model: the earth's gravitation has a J2 term the navigation
// computer's model lacks (by default: J2 truth, sphere in the computer).
#include "lib/truth/earth_model.h"
#include "lib/truth/effects/effects.h"

namespace insmc::effects {
namespace {

constexpr EffectParameter kParameters[] = {
    {"j2", Dimension::kDimensionless, kEarthJ2,
     "J2 of the truth beyond the computer's model (default: the earth's whole J2)",
     ParameterRange::kAny, 0.0, EffectMagnitude::kScaled},
};

void realize(const EffectSpec& spec, const EffectContext&, NormalDraws&, Perturbations& p) {
  p.extra_j2 += spec.value("j2");
}

}  // namespace

const EffectDefinition& gravity_model() {
  static const EffectDefinition d{
      {"gravity_model",
       "gravity-model error: the true gravitation has a J2 term the computer does not model; the "
       "site's plumb line and the computed gravitation both differ",
       kParameters, false},
      &realize};
  return d;
}

}  // namespace insmc::effects
