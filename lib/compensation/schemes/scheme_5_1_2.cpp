#include "lib/compensation/schemes/schemes.h"

namespace insmc::schemes {

/// 5.1.2: Û2 at point 2, Û3 to the gyro torquers (5.5), then a
/// realignment. The torquer rates act through the realignment and after it:
/// the level-platform drift becomes ω_do + ω_cp everywhere (5.6), (5.7).
const SchemeDefinition& scheme_5_1_2() {
  static const SchemeDefinition d{
      .name = "5.1.2",
      .equations = "(5.5)-(5.7)",
      .realigns = true,
      .uses_test_run = true,
      .measurement_error_groups = {"realignment_azimuth_error"},
      .position_map =
          [](const SchemeMapContext& c, ExtendedMap& e) {
            scheme_terms::add_u2_step(c, e);
            e.middleCols<3>(z_slot::kU3) = scheme_terms::u3_to_torquers(c);
          },
      .truth_action =
          [](const TruthSchemeContext& c, TruthOptions& o, UncertaintyVector& x) {
            o.accel_compensation.step_mps2 = -c.model.gravity_mps2 * c.estimates.u2;
            scheme_terms::apply_u3_to_torquers(c, x);
          },
  };
  return d;
}

}  // namespace insmc::schemes
