// thermal_transient: bias and drift settling after switch-on, the same in
// every run, so a deterministic signature fitted by its amplitudes.
#include <cmath>
#include <string>

#include "montecarlo/records/gap/candidates/common.h"
#include "montecarlo/records/gap/candidates/definitions.h"

namespace insmc::gap::candidates {

Candidate thermal_transient() {
  return {"thermal_transient",
          "bias and drift settling exponentially after switch-on, the same in every run (a design effect): "
          "a(t) = b (e^{-t/tau} − 1), θ(t) = d (tau (1 − e^{-t/tau}) − t) on every axis; b, d fitted at switch-over and reported at switch-on (warm-up: header warmup_s, else 900 s)",
          {amplitude("bias", Dimension::kAcceleration, 10 * kMgToMps2, "10 times Table 3.1's 1 mg bias"),
           amplitude("drift", Dimension::kAngularRate, 300 * kMeruToRadps, "30 times Table 3.1's 10 meru drift"),
           searched("tau", Dimension::kTime, {600.0, 1200.0, 2400.0}, 1.0, magnitude_limit(Dimension::kTime),
                    "1 s (a step at switch-over) to 48 h, the longest run (a drift that never settles)")},
          [](const LayoutContext& ctx, std::span<const double> p) {
            const double tau = p[2];
            const Eigen::MatrixXd cols = signature_columns(ctx, "thermal:" + std::to_string(tau), 2,
                                                           [tau](double t, runs::Columns3& a, runs::Columns3& th) {
                                                             const double decay = std::exp(-t / tau);
                                                             a.setZero();
                                                             th.setZero();
                                                             a.col(0).setConstant(decay - 1.0);
                                                             th.col(1).setConstant(tau * (1.0 - decay) - t);
                                                           });
            // b(t) = b0 + b0 (e^{-t/tau} − 1): the part at switch-over acts as
            // the fixed bias δf and drift ω_do do, through the alignment (their
            // columns of H_x); the settling is the signature above.
            const Eigen::MatrixXd& H = ctx.base->H_x;
            const Eigen::VectorXd fixed_bias = H.middleCols<3>(uncertainty_slot::kAccelBias).rowwise().sum();
            const Eigen::VectorXd fixed_drift = H.middleCols<3>(uncertainty_slot::kGyroDrift).rowwise().sum();
            runs::Extension e;
            e.mean = p[0] * (cols.col(0) + fixed_bias) + p[1] * (cols.col(1) + fixed_drift);
            return e;
          },
          // b and d are fitted at switch-over; the effect is defined at
          // switch-on, a warm-up earlier: b_on = b e^{warmup/tau} (each
          // resampled fit with its own tau, so tau's spread carries through).
          [](std::span<double> p, const runs::RecordSite& site) {
            const double grown = std::exp(site.warmup_s / p[2]);
            p[0] *= grown;
            p[1] *= grown;
          },
          "another warm-up time before switch-over (the transient decays from switch-on)"};
}

}  // namespace insmc::gap::candidates
