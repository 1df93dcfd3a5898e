// sway: the vehicle moves on its gear (wind, loading): a band-limited
// displacement, whose acceleration (u)r̈ the accelerometers see and whose
// velocity at switch-over is the velocity wiggle the computer does not know.
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "lib/common/input_error.h"
#include "lib/truth/effects/effects.h"

namespace insmc::effects {
namespace {

constexpr EffectParameter kParameters[] = {
    {"accel_rms", Dimension::kAcceleration, 5.0 * kMgToMps2,
     "RMS of the horizontal sway acceleration per axis", ParameterRange::kNonNegative, kGravityMps2, EffectMagnitude::kScaled},
    {"period_min", Dimension::kTime, 2.0, "shortest sway period", ParameterRange::kPositive, 3600.0},
    {"period_max", Dimension::kTime, 20.0, "longest sway period", ParameterRange::kPositive, 3600.0},
    {"vertical_ratio", Dimension::kDimensionless, 0.3,
     "vertical sway amplitude relative to the horizontal", ParameterRange::kNonNegative, 10.0},
    {"components", Dimension::kDimensionless, 4.0,
     "sinusoids per axis (periods log-uniform in [period_min, period_max], random phases)",
     ParameterRange::kPositive, 64.0},
};

// The periods in order and a whole number of sinusoids.
void check(const EffectSpec& spec, std::string_view field) {
  if (spec.value("period_min") > spec.value("period_max"))
    throw InputError(fmt::format("{} sway.period_min", field), format_quantity(spec.value("period_min"), Dimension::kTime),
                     "must be <= period_max");
  const double n = spec.value("components");
  if (n != std::round(n) || n > 64)
    throw InputError(fmt::format("{} sway.components", field), fmt::format("{}", n),
                     "must be a whole number from 1 to 64");
}

void realize(const EffectSpec& spec, const EffectContext&, NormalDraws& draws, Perturbations& p) {
  const double rms = spec.value("accel_rms");
  const double p_min = spec.value("period_min"), p_max = spec.value("period_max");
  const int count = static_cast<int>(std::lround(spec.value("components")));
  const double ratio[3] = {1.0, 1.0, spec.value("vertical_ratio")};
  // K sinusoids of equal acceleration amplitude a: K a²/2 = rms².
  const double accel_amplitude = rms * std::sqrt(2.0 / count);
  for (int axis = 0; axis < 3; ++axis) {
    for (int k = 0; k < count; ++k) {
      const double period = p_min * std::pow(p_max / p_min, draws.next_uniform());
      const double phase = 2.0 * std::numbers::pi * draws.next_uniform();
      const double omega = 2.0 * std::numbers::pi / period;
      SwayComponent c;
      c.amplitude_n_m[axis] = ratio[axis] * accel_amplitude / (omega * omega);
      c.period_s = period;
      c.phase_rad = phase;
      p.sway.push_back(c);
    }
  }
}

}  // namespace

const EffectDefinition& sway() {
  static const EffectDefinition d{
      {"sway",
       "band-limited motion of the vehicle on its gear: disturbance acceleration in the "
       "accelerometer data and an initial velocity error (velocity wiggle)",
       kParameters, true, RawSensor::kNone, false, &check},
      &realize};
  return d;
}

}  // namespace insmc::effects
