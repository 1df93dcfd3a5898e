#include "lib/preflight/observables.h"

#include <cmath>

#include "lib/propagation/closed_form.h"

namespace insmc {

Sensitivity3 paper_a1(const ShortRunMatrices& m, const ModelOptions& o) {
  return m.u2 + m.initial_position_m / o.radius_m;  // (4.4b)
}

Sensitivity3 paper_accelerometer_error(const ShortRunMatrices& m, double t, const ModelOptions& o) {
  const double p = o.earth_rate_radps * t;
  return o.gravity_mps2 * (paper_a1(m, o) + p * m.u3 + 0.5 * p * p * m.u4);  // (4.4)
}

Sensitivity3 paper_test_position_change(const ShortRunMatrices& m, double t, const ModelOptions& o) {
  const ShortRunFunctions f = short_run_functions_3_29(t, o);
  return f.initial_velocity_s * m.initial_velocity_mps +
         o.radius_m * (f.u2 * m.u2 + f.u3 * m.u3 + f.u4 * m.u4);  // (4.5)
}

ResolutionLimits pulse_resolution_limits(double dv, double T, const ModelOptions& o) {
  const double g = o.gravity_mps2, w = o.earth_rate_radps;
  // (4.6): A1 ≥ 3ΔV/(Tg), U3 ≥ 6ΔV/(ω_ie T² g), U4 ≥ 18ΔV/(ω_ie² T³ g).
  return {3 * dv / (T * g), 6 * dv / (w * T * T * g), 18 * dv / (w * w * T * T * T * g)};
}

}  // namespace insmc
