// velocity_random_walk: white accelerometer noise, a velocity random walk
// in r and white noise in f (random_process.h).
#include "montecarlo/records/gap/candidates/common.h"
#include "montecarlo/records/gap/candidates/definitions.h"
#include "montecarlo/records/gap/candidates/random_process.h"

namespace insmc::gap::candidates {

Candidate velocity_random_walk() {
  return {"velocity_random_walk",
          "white accelerometer noise: white in f (q/τ), a velocity random walk in r (σ after 1 h)",
          {searched("velocity_1h", Dimension::kVelocity, log_grid(0.01, 10, 1.0), 0.3e-6,
                    magnitude_limit(Dimension::kVelocity),
                    "1e-6 of Table 3.1's 0.3 m/s initial velocity up to the 10 m/s the model describes")},
          [](const LayoutContext& ctx, std::span<const double> p) {
            // The walk's increments over τ that the knots and bridge modes
            // do not carry are white in f: q/τ.
            runs::Extension e = process_extension(ctx, Drive::kVelocity, p[0], 0.0);
            const double q = p[0] * p[0] / 3600.0;
            e.noise_var_add = f_noise(ctx, Eigen::Vector3d::Constant(q / ctx.site->filter_interval_s));
            return e;
          },
          {},
          "the accelerometers' raw outputs (import-imu's raw-sensor stage) or f sampled faster"};
}

}  // namespace insmc::gap::candidates
