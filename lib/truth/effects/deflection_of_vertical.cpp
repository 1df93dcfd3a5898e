// deflection_of_vertical: the site's plumb line deviates from the reference
// field's by more than Table 3.1's ξ, η (one site: a fixed value per run).
#include "lib/truth/effects/effects.h"

namespace insmc::effects {
namespace {

constexpr EffectParameter kParameters[] = {
    {"xi", Dimension::kAngle, 0.3 * kMradToRad,
     "ξ, deflection about east (added to x's deflection_xi)", ParameterRange::kAny, 0.0, EffectMagnitude::kScaled},
    {"eta", Dimension::kAngle, 0.3 * kMradToRad,
     "η, deflection about north (added to x's deflection_eta)", ParameterRange::kAny, 0.0, EffectMagnitude::kScaled},
};

void realize(const EffectSpec& spec, const EffectContext&, NormalDraws&, Perturbations& p) {
  p.deflection_rad += Eigen::Vector2d(spec.value("xi"), spec.value("eta"));
}

}  // namespace

const EffectDefinition& deflection_of_vertical() {
  static const EffectDefinition d{
      {"deflection_of_vertical",
       "deflection of the vertical at the site beyond Table 3.1 (2.8b): the leveling loops find "
       "the deflected plumb line, the computer's gravitation does not have it",
       kParameters, false},
      &realize};
  return d;
}

}  // namespace insmc::effects
