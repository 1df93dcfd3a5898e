// gyro_drift_instability: the gyro drift wanders after the alignment has
// taken its value; the platform angle is its integral (random_process.h).
#include "montecarlo/records/gap/candidates/common.h"
#include "montecarlo/records/gap/candidates/definitions.h"
#include "montecarlo/records/gap/candidates/random_process.h"

namespace insmc::gap::candidates {

Candidate gyro_drift_instability() {
  return {"gyro_drift_instability",
          "gyro drift wandering as a random walk (tau 0, σ after 1 h) or Gauss–Markov process",
          {searched("sigma", Dimension::kAngularRate, log_grid(0.1, 100, kMeruToRadps), 1e-5 * kMeruToRadps,
                    magnitude_limit(Dimension::kAngularRate),
                    "1e-6 of Table 3.1's 10 meru drift up to the 10,000 meru the small-angle model describes"),
           searched("tau", Dimension::kTime, {0.0, 300.0, 1200.0, 3600.0}, 1.0, magnitude_limit(Dimension::kTime),
                    "1 s (shorter is white rate noise) to 48 h, the longest run; a random walk is its upper end")},
          [](const LayoutContext& ctx, std::span<const double> p) {
            return process_extension(ctx, Drive::kRate, p[0], p[1]);
          },
          {},
          "a longer stationary test run (the tilt's growth beyond the drift's correlation time)"};
}

}  // namespace insmc::gap::candidates
