// alignment_transient: the alignment loops have not settled at switch-over;
// what is left of the coarse-alignment error becomes a misalignment step.
#include <cmath>

#include "lib/truth/effects/effects.h"

namespace insmc::effects {
namespace {

// A coarse alignment leaves up to a radian (the truth simulator turns the
// platform by quaternions, so no small-angle limit applies); the transient
// decays in the fine alignment.
constexpr double kCoarseAlignmentLimitRad = 1.0;

constexpr EffectParameter kParameters[] = {
    {"level_initial", Dimension::kAngle, 5.0 * kMradToRad,
     "1σ level error per axis at the start of the fine alignment", ParameterRange::kNonNegative,
     kCoarseAlignmentLimitRad, EffectMagnitude::kScaled},
    {"azimuth_initial", Dimension::kAngle, 20.0 * kMradToRad,
     "1σ azimuth error at the start of the fine alignment", ParameterRange::kNonNegative,
     kCoarseAlignmentLimitRad, EffectMagnitude::kScaled},
    {"duration", Dimension::kTime, 600.0, "fine-alignment time", ParameterRange::kPositive},
    {"level_tau", Dimension::kTime, 120.0, "settling time constant of the leveling loops",
     ParameterRange::kPositive},
    {"azimuth_tau", Dimension::kTime, 200.0,
     "settling time constant of the azimuth loop (theodolite or gyrocompass)",
     ParameterRange::kPositive},
};

void realize(const EffectSpec& spec, const EffectContext&, NormalDraws& draws, Perturbations& p) {
  const double T = spec.value("duration");
  const double level = spec.value("level_initial") * std::exp(-T / spec.value("level_tau"));
  const double azimuth = spec.value("azimuth_initial") * std::exp(-T / spec.value("azimuth_tau"));
  const Vec3 z = normal3(draws);
  p.misalignment_step_rad += Vec3(level * z.x(), level * z.y(), azimuth * z.z());
}

}  // namespace

const EffectDefinition& alignment_transient() {
  static const EffectDefinition d{
      {"alignment_transient",
       "alignment loops not settled at switch-over: the initial error decayed by "
       "e^{-duration/tau} remains as a random misalignment (level and azimuth)",
       kParameters, true},
      &realize};
  return d;
}

}  // namespace insmc::effects
