// accel_bias_instability: the accelerometer bias wanders after the alignment
// has taken its value (random_process.h).
#include "montecarlo/records/gap/candidates/common.h"
#include "montecarlo/records/gap/candidates/definitions.h"
#include "montecarlo/records/gap/candidates/random_process.h"

namespace insmc::gap::candidates {

Candidate accel_bias_instability() {
  return {"accel_bias_instability",
          "accelerometer bias wandering as a random walk (tau 0, σ after 1 h) or Gauss–Markov process",
          {searched("sigma", Dimension::kAcceleration, log_grid(2, 2000, kUg), 1e-6 * kMgToMps2,
                    magnitude_limit(Dimension::kAcceleration),
                    "1e-6 of Table 3.1's 1 mg bias up to the 100 mg the linearized model describes"),
           searched("tau", Dimension::kTime, {0.0, 300.0, 1200.0, 3600.0}, 1.0, magnitude_limit(Dimension::kTime),
                    "1 s (shorter is white noise in f) to 48 h, the longest run; a random walk is its upper end")},
          [](const LayoutContext& ctx, std::span<const double> p) {
            return process_extension(ctx, Drive::kAccel, p[0], p[1]);
          },
          {},
          "a longer stationary test run (the accelerometers' wander beyond its correlation time)"};
}

}  // namespace insmc::gap::candidates
