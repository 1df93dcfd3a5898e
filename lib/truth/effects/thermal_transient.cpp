// thermal_transient: bias and drift settle exponentially after switch-on;
// the alignment nulls the values at switch-over, the navigation sees the
// rest of the settling.
#include <cmath>

#include "lib/truth/effects/effects.h"

namespace insmc::effects {
namespace {

constexpr EffectParameter kParameters[] = {
    {"bias", Dimension::kAcceleration, 0.1 * kMgToMps2,
     "accelerometer bias offset at switch-on, all axes, decaying with tau", ParameterRange::kAny, 0.0, EffectMagnitude::kScaled},
    {"drift", Dimension::kAngularRate, 2.0 * kMeruToRadps,
     "gyro drift offset at switch-on, all gyros, decaying with tau", ParameterRange::kAny, 0.0, EffectMagnitude::kScaled},
    {"tau", Dimension::kTime, 1200.0, "thermal time constant", ParameterRange::kPositive},
    {"warmup", Dimension::kTime, 900.0, "time from switch-on to switch-over (the alignment)",
     ParameterRange::kNonNegative, 0.0, EffectMagnitude::kFixed, RawSensorLimit::kNone, "warmup_s"},
};

void realize(const EffectSpec& spec, const EffectContext&, NormalDraws&, Perturbations& p) {
  const double tau = spec.value("tau");
  const double left = std::exp(-spec.value("warmup") / tau);  // fraction left at switch-over
  ExponentialTerm bias{Vec3::Constant(spec.value("bias") * left), tau};
  ExponentialTerm drift{Vec3::Constant(spec.value("drift") * left), tau};
  p.alignment_bias_mps2 += bias.amplitude;
  p.alignment_drift_radps += drift.amplitude;
  p.bias_transients.push_back(bias);
  p.drift_transients.push_back(drift);
}

}  // namespace

const EffectDefinition& thermal_transient() {
  static const EffectDefinition d{
      {"thermal_transient",
       "exponential settling of accelerometer bias and gyro drift after switch-on: "
       "b(t) = bias e^{-(warmup + t)/tau}, likewise the drift",
       kParameters, false},
      &realize};
  return d;
}

}  // namespace insmc::effects
