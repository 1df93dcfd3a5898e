// angle_random_walk: white gyro rate noise, so the platform angle itself
// walks (random_process.h).
#include "montecarlo/gap/candidates/common.h"
#include "montecarlo/gap/candidates/definitions.h"
#include "montecarlo/gap/candidates/random_process.h"

namespace insmc::gap::candidates {

Candidate angle_random_walk() {
  return {"angle_random_walk", "white gyro rate noise: the platform angle walks (σ after 1 h)",
          {{"angle_1h", Dimension::kAngle, log_grid(0.005, 10, kMradToRad)}},
          [](const LayoutContext& ctx, std::span<const double> p) {
            return process_extension(ctx, Drive::kAngle, p[0], 0.0);
          }};
}

}  // namespace insmc::gap::candidates
