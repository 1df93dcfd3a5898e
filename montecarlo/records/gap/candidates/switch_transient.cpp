// switch_transient: steps at switch-over beyond Table 3.1, in the
// misalignment (to the rotation's second order) and the accelerometer bias.
#include "montecarlo/records/gap/candidates/common.h"
#include "montecarlo/records/gap/candidates/definitions.h"
#include "montecarlo/records/gap/candidates/misalignment_second_order.h"

namespace insmc::gap::candidates {

Candidate switch_transient() {
  return {"switch_transient",
          "steps at switch-over beyond Table 3.1: misalignment (all axes) and accelerometer bias",
          {searched("misalignment", Dimension::kAngle, scaled({0, 0.03, 0.1, 0.3, 1, 3, 10}, kMradToRad),
                    0.5e-6 * kMradToRad, magnitude_limit(Dimension::kAngle),
                    "a floor of 1e-6 of Table 3.1's 0.5 mrad for 0 (none) up to the 100 mrad of the small-angle model"),
           searched("bias", Dimension::kAcceleration, scaled({0, 20, 50, 100, 200, 500, 1000, 3000}, kUg),
                    1e-6 * kMgToMps2, magnitude_limit(Dimension::kAcceleration),
                    "a floor of 1e-6 of Table 3.1's 1 mg for 0 (none) up to the 100 mg the linearized model describes")},
          [](const LayoutContext& ctx, std::span<const double> p) {
            runs::Extension e;
            e.x_var_add.segment<3>(uncertainty_slot::kMisalignAlign).setConstant(p[0] * p[0]);
            e.x_var_add.segment<2>(uncertainty_slot::kBiasChangeAlign).setConstant(p[1] * p[1]);
            e.x_var_add[uncertainty_slot::kAccelBias + 2] = p[1] * p[1];
            add_misalignment_second_order(ctx, Eigen::Vector3d::Constant(p[0]), e);
            return e;
          },
          {},
          "repeated alignments of one unit (a step at switch-over is drawn anew each time)"};
}

}  // namespace insmc::gap::candidates
