#include "lib/compensation/schemes/schemes.h"

namespace insmc::schemes {

/// 5.1.1: Û2 at point 2 (5.2), Û3 through integrators into point 2 (5.3),
/// then a realignment; the clock starts at the new switch-over.
const SchemeDefinition& scheme_5_1_1() {
  static const SchemeDefinition d{
      .name = "5.1.1",
      .equations = "(5.2)-(5.4)",
      .realigns = true,
      .uses_test_run = true,
      .measurement_error_groups = {"realignment_azimuth_error"},
      .position_map =
          [](const SchemeMapContext& c, ExtendedMap& e) {
            scheme_terms::add_u2_step(c, e);                                                 // (5.2)
            e.middleCols<3>(z_slot::kU3) = scheme_terms::u3_ramp_per_unit(c) * Mat3::Identity();  // (5.3)
          },
      .truth_action =
          [](const TruthSchemeContext& c, TruthOptions& o, UncertaintyVector&) {
            const double g = c.model.gravity_mps2, w = c.model.earth_rate_radps;
            o.accel_compensation.step_mps2 = -g * c.estimates.u2;     // (5.2)
            o.accel_compensation.ramp_mps3 = -g * w * c.estimates.u3;  // (5.3)
          },
  };
  return d;
}

}  // namespace insmc::schemes
