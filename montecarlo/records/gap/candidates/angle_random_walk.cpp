// angle_random_walk: white gyro rate noise, so the platform angle itself
// walks (random_process.h).
#include "montecarlo/records/gap/candidates/common.h"
#include "montecarlo/records/gap/candidates/definitions.h"
#include "montecarlo/records/gap/candidates/random_process.h"

namespace insmc::gap::candidates {

Candidate angle_random_walk() {
  return {"angle_random_walk", "white gyro rate noise: the platform angle walks (σ after 1 h)",
          {searched("angle_1h", Dimension::kAngle, log_grid(0.005, 10, kMradToRad), 0.5e-6 * kMradToRad,
                    magnitude_limit(Dimension::kAngle),
                    "1e-6 of Table 3.1's 0.5 mrad misalignment up to the 100 mrad of the small-angle model")},
          [](const LayoutContext& ctx, std::span<const double> p) {
            return process_extension(ctx, Drive::kAngle, p[0], 0.0);
          },
          {},
          "the gyros' raw outputs (import-imu's raw-sensor stage) or a longer stationary test run"};
}

}  // namespace insmc::gap::candidates
