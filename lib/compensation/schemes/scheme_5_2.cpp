#include "lib/compensation/schemes/schemes.h"

namespace insmc::schemes {

/// 5.2: position data only, no realignment; from T, −g(Û2 + Û3 ω_ie T) at
/// point 2 and −g ω_ie Û3 through integrators, with the velocity and
/// position integrators reset at T (points 5, 6) (5.8), (5.9).
const SchemeDefinition& scheme_5_2() {
  static const SchemeDefinition d{
      .name = "5.2",
      .equations = "(5.8), (5.9)",
      .resets_at_test_end = true,
      .uses_test_run = true,
      .measurement_error_groups = {"reset_position_error", "reset_velocity_error"},
      .position_map =
          [](const SchemeMapContext& c, ExtendedMap& e) {
            const double g = c.model.gravity_mps2, w = c.model.earth_rate_radps, ws = c.model.schuler_radps();
            const double T = c.test_duration_s, tau = c.tau_s;
            scheme_terms::add_u2_step(c, e);
            e.middleCols<3>(z_slot::kU3) =
                -g * w * (T * scheme_terms::step_response(tau, ws) + scheme_terms::ramp_response(tau, ws)) * Mat3::Identity();
          },
      .truth_action =
          [](const TruthSchemeContext& c, TruthOptions& o, UncertaintyVector&) {
            const double g = c.model.gravity_mps2, w = c.model.earth_rate_radps, T = c.test_duration_s;
            o.accel_compensation.step_mps2 = -g * (c.estimates.u2 + w * T * c.estimates.u3);
            o.accel_compensation.ramp_mps3 = -g * w * c.estimates.u3;
          },
  };
  return d;
}

}  // namespace insmc::schemes
