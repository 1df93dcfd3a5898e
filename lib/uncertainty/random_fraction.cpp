#include "lib/uncertainty/random_fraction.h"

#include "lib/common/assert.h"
#include "lib/uncertainty/uncertainty_vector.h"
#include "lib/units/units.h"

namespace insmc {

void apply_random_fraction(UncertaintyModel& model, double fraction) {
  INSMC_ASSERT(fraction >= 0 && fraction <= 1, "random fraction {}", fraction);
  constexpr double kZetaTotalRad = 1e-3;            // Table 3.1: ζ < 1 mrad
  constexpr double kDfTotalMps2 = 0.1 * kMgToMps2;   // Table 3.1: ∂f < 0.1 mg
  for (int k = 0; k < 3; ++k) {
    model.at(uncertainty_slot::kMisalignConst + k).bound_si = (1 - fraction) * kZetaTotalRad;
    model.at(uncertainty_slot::kMisalignAlign + k).bound_si = fraction * kZetaTotalRad;
  }
  for (int k = 0; k < 2; ++k) {
    model.at(uncertainty_slot::kBiasChangeConst + k).bound_si = (1 - fraction) * kDfTotalMps2;
    model.at(uncertainty_slot::kBiasChangeAlign + k).bound_si = fraction * kDfTotalMps2;
  }
}

}  // namespace insmc
