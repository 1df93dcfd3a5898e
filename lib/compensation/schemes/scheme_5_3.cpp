#include "lib/compensation/schemes/schemes.h"

namespace insmc::schemes {

/// 5.3: position and filtered accelerometer data, no realignment; from T,
/// −Δf̂(T) of (5.10) at point 2 and −g ω_ie Û3 (the accelerometer data's
/// slope, (5.12)) through integrators, with the resets at T (5.11).
const SchemeDefinition& scheme_5_3() {
  static const SchemeDefinition d{
      .name = "5.3",
      .equations = "(5.10)-(5.12)",
      .resets_at_test_end = true,
      .uses_test_run = true,
      .measurement_error_groups = {"reset_position_error", "reset_velocity_error"},
      .position_map =
          [](const SchemeMapContext& c, ExtendedMap& e) {
            e.middleCols<3>(z_slot::kDfT) = -scheme_terms::step_response(c.tau_s, c.model.schuler_radps()) * Mat3::Identity();
            e.middleCols<3>(z_slot::kU3Accel) = scheme_terms::u3_ramp_per_unit(c) * Mat3::Identity();
          },
      .truth_action =
          [](const TruthSchemeContext& c, TruthOptions& o, UncertaintyVector&) {
            o.accel_compensation.step_mps2 = -c.estimates.df_at_test_end_mps2;
            o.accel_compensation.ramp_mps3 = -c.model.gravity_mps2 * c.model.earth_rate_radps * c.estimates.u3_accel;
          },
  };
  return d;
}

}  // namespace insmc::schemes
