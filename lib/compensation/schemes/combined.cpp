#include "lib/compensation/schemes/schemes.h"

namespace insmc::schemes {

/// 5.1.1 with 5.1.2 (end of 5.1.2): Û2 at point 2, Û3 to the torquers where
/// they help (5.5), through integrators for the rest (5.3), then a
/// realignment.
const SchemeDefinition& combined() {
  static const SchemeDefinition d{
      .name = "combined",
      .equations = "(5.2)-(5.7)",
      .realigns = true,
      .uses_test_run = true,
      .measurement_error_groups = {"realignment_azimuth_error"},
      .position_map =
          [](const SchemeMapContext& c, ExtendedMap& e) {
            scheme_terms::add_u2_step(c, e);
            e.middleCols<3>(z_slot::kU3) = scheme_terms::u3_to_torquers(c) + scheme_terms::u3_ramp_per_unit(c) *
                                                                             scheme_terms::combined_integrator_selection(c.system);
          },
      .truth_action =
          [](const TruthSchemeContext& c, TruthOptions& o, UncertaintyVector& x) {
            const double g = c.model.gravity_mps2, w = c.model.earth_rate_radps;
            o.accel_compensation.step_mps2 = -g * c.estimates.u2;
            scheme_terms::apply_u3_to_torquers(c, x);
            o.accel_compensation.ramp_mps3 = -g * w * (scheme_terms::combined_integrator_selection(c.system) * c.estimates.u3);
          },
  };
  return d;
}

}  // namespace insmc::schemes
