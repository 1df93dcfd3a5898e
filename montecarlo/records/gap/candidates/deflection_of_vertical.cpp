// deflection_of_vertical: the site's deflection beyond Table 3.1, the same
// in every run: a fixed value of ξ, η through the alignment (2.8b).
#include "lib/units/units.h"
#include "montecarlo/records/gap/candidates/common.h"
#include "montecarlo/records/gap/candidates/definitions.h"

namespace insmc::gap::candidates {

Candidate deflection_of_vertical() {
  return {"deflection_of_vertical",
          "deflection of the vertical at the site beyond Table 3.1, the same in every run: ξ, η of (2.8b) with a "
          "fixed value",
          {amplitude("xi", Dimension::kAngle, 20 * kMradToRad, "200 times Table 3.1's 0.1 mrad deflection"),
           amplitude("eta", Dimension::kAngle, 20 * kMradToRad, "200 times Table 3.1's 0.1 mrad deflection")},
          [](const LayoutContext& ctx, std::span<const double> p) {
            runs::Extension e;
            e.mean = p[0] * ctx.base->H_x.col(uncertainty_slot::kDeflection) + p[1] * ctx.base->H_x.col(uncertainty_slot::kDeflection + 1);
            return e;
          },
          {},
          "a second site (the deflection belongs to the site: the same in every run)"};
}

}  // namespace insmc::gap::candidates
