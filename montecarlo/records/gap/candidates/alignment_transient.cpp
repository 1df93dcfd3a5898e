// alignment_transient: alignment loops not settled at switch-over, a level
// and an azimuth misalignment beyond ζ_r, to the rotation's second order.
#include "montecarlo/records/gap/candidates/common.h"
#include "montecarlo/records/gap/candidates/definitions.h"
#include "montecarlo/records/gap/candidates/misalignment_second_order.h"

namespace insmc::gap::candidates {

Candidate alignment_transient() {
  return {"alignment_transient",
          "alignment loops not settled at switch-over: a level and an azimuth misalignment beyond ζ_r (to the "
          "rotation's second order)",
          {searched("level", Dimension::kAngle, scaled({0, 0.03, 0.1, 0.3, 1, 3}, kMradToRad), 0.5e-6 * kMradToRad,
                    magnitude_limit(Dimension::kAngle),
                    "a floor of 1e-6 of Table 3.1's 0.5 mrad for 0 (none) up to the 100 mrad of the small-angle model"),
           searched("azimuth", Dimension::kAngle, scaled({0.3, 1, 3, 10, 30, 100}, kMradToRad), 0.5e-6 * kMradToRad,
                    magnitude_limit(Dimension::kAngle),
                    "a floor of 1e-6 of Table 3.1's 0.5 mrad for 0 (none) up to the 100 mrad of the small-angle model")},
          [](const LayoutContext& ctx, std::span<const double> p) {
            runs::Extension e;
            e.x_var_add.segment<3>(uncertainty_slot::kMisalignAlign) = Eigen::Vector3d(p[0] * p[0], p[0] * p[0], p[1] * p[1]);
            add_misalignment_second_order(ctx, Eigen::Vector3d(p[0], p[0], p[1]), e);
            return e;
          },
          {},
          "a longer fine alignment (what is left of the initial error decays with it)"};
}

}  // namespace insmc::gap::candidates
