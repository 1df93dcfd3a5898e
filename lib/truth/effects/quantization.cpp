// quantization: ΔV pulses of a weight other than the model's.
#include "lib/truth/effects/effects.h"

namespace insmc::effects {
namespace {

constexpr EffectParameter kParameters[] = {
    {"dv_pulse", Dimension::kVelocity, 0.5 * kFtpsToMps,
     "pulse weight of the accelerometer velocity increments (the model's is 0.1 ft/s)",
     ParameterRange::kPositive, 0.0, EffectMagnitude::kExcessOverModelPulse, RawSensorLimit::kVelocityQuantization},
};

void realize(const EffectSpec& spec, const EffectContext&, NormalDraws&, Perturbations& p) {
  p.dv_pulse_mps = spec.value("dv_pulse");
}

}  // namespace

const EffectDefinition& quantization() {
  static const EffectDefinition d{
      {"quantization",
       "accelerometer pulses of another weight than the model's (remainder carried); "
       "coarser pulses add sawtooth velocity errors to the navigation and counting noise to the "
       "filtered accelerometer data",
       kParameters, false, RawSensor::kNone, true},
      &realize};
  return d;
}

}  // namespace insmc::effects
