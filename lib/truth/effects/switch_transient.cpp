// switch_transient: electrical transients when the alignment electronics
// are disconnected: steps in misalignment and accelerometer bias beyond
// Table 3.1's ζ_r and ∂f.
#include "lib/truth/effects/effects.h"

namespace insmc::effects {
namespace {

constexpr EffectParameter kParameters[] = {
    {"misalignment", Dimension::kAngle, 0.3 * kMradToRad,
     "1σ misalignment step per axis at switch-over", ParameterRange::kNonNegative, 0.0, EffectMagnitude::kScaled},
    {"bias", Dimension::kAcceleration, 0.1 * kMgToMps2,
     "1σ accelerometer bias step per axis at switch-over", ParameterRange::kNonNegative, 0.0, EffectMagnitude::kScaled},
};

void realize(const EffectSpec& spec, const EffectContext&, NormalDraws& draws, Perturbations& p) {
  p.misalignment_step_rad += spec.value("misalignment") * normal3(draws);
  p.nav_bias_step_mps2 += spec.value("bias") * normal3(draws);
}

}  // namespace

const EffectDefinition& switch_transient() {
  static const EffectDefinition d{
      {"switch_transient",
       "steps in misalignment and accelerometer bias at switch-over beyond Table 3.1 "
       "(normal, per axis)",
       kParameters, true},
      &realize};
  return d;
}

}  // namespace insmc::effects
