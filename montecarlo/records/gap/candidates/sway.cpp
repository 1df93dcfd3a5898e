// sway: the vehicle moving on its gear, seen through the τ box filter in f
// and as a velocity and displacement at switch-over the computer does not know.
#include <cmath>
#include <numbers>
#include <string>

#include "montecarlo/records/gap/candidates/common.h"
#include "montecarlo/records/gap/candidates/definitions.h"

namespace insmc::gap::candidates {

Candidate sway() {
  return {"sway",
          "vehicle sway of periods 2-20 s: residual acceleration in f after the τ box filter, its velocity and "
          "displacement at switch-over, and the counters cycling from the start",
          {searched("accel_rms", Dimension::kAcceleration, log_grid(0.2, 200, kMgToMps2), 1e-6 * kMgToMps2,
                    kGravityMps2, "1e-6 of Table 3.1's 1 mg bias up to 1 g, the truth effect's own limit "
                    "(lib/truth/effects/sway.cpp)")},
          [](const LayoutContext& ctx, std::span<const double> p) {
            // Log-uniform periods in [2, 20] s: mean power gain of the box
            // filter sinc²(π τ/P), mean 1/ω² for the velocity and 1/ω⁴ for
            // the displacement.
            constexpr double p1 = 2.0, p2 = 20.0, vertical = 0.3;
            const double tau = ctx.site->filter_interval_s, two_pi = 2.0 * std::numbers::pi;
            double gain = 0.0;
            constexpr int n = 200;
            for (int i = 0; i < n; ++i) {
              const double period = p1 * std::pow(p2 / p1, (i + 0.5) / n);
              const double x = std::numbers::pi * tau / period;
              gain += std::pow(std::sin(x) / x, 2) / n;
            }
            const double inv_w2 = (p2 * p2 - p1 * p1) / (2 * std::log(p2 / p1)) / std::pow(two_pi, 2);
            const double inv_w4 = (std::pow(p2, 4) - std::pow(p1, 4)) / (4 * std::log(p2 / p1)) / std::pow(two_pi, 4);
            const double a2 = p[0] * p[0];
            const Eigen::Vector3d axes(1, 1, vertical * vertical);
            runs::Extension e;
            e.noise_var_add = f_noise(ctx, a2 * gain * axes);
            e.x_var_add.segment<3>(uncertainty_slot::kInitialVelocity) = a2 * inv_w2 * axes;
            // The displacement at switch-over is an initial position error the
            // computer does not know: r = r0 cos(ω_s t) (3.24). Table 3.1 has
            // one north (δL0) and down (δh), none east.
            // After a reset the computer takes its stationary position again;
            // after a realignment a new displacement is its own cause.
            const runs::Layout& l = *ctx.layout;
            const bool restart = l.nav == runs::NavSegment::kRestart;
            e.columns = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(l.rows.size()), restart ? 6 : 3);
            const double ws = ctx.site->model.schuler_radps();
            for (std::size_t i = 0; i < l.rows.size(); ++i) {
              const runs::ObservationRow& row = l.rows[i];
              const bool nav = static_cast<int>(i) >= l.test_rows;
              if (row.quantity != runs::Quantity::kR || (nav && l.nav == runs::NavSegment::kReset)) continue;
              e.columns(static_cast<Eigen::Index>(i), row.axis + (l.restarted(i) ? 3 : 0)) = std::cos(ws * l.clock_s(i));
            }
            e.column_var = (a2 * inv_w4 * axes).replicate(restart ? 2 : 1, 1);
            // The counters count the sway too (pulse_counting.h), at the
            // site's pulse weight (replacing a counting another extension
            // set). It depends on the motion only through which axes cycle
            // from the start: none is the base model's own counting of the
            // layout, each other pattern is computed once per layout.
            const double pulse = ctx.site->dv_pulse_mps;
            const Eigen::Vector3d velocity_rms = p[0] * std::sqrt(inv_w2) * axes.cwiseSqrt();
            runs::CountedMotion cycling;
            std::string key = "sway counting";
            for (int k = 0; k < 3; ++k) {
              const bool cycles = velocity_rms[k] >= 0.5 * pulse;
              cycling.velocity_rms_mps[k] = cycles ? velocity_rms[k] : 0.0;
              key += cycles ? '1' : '0';
            }
            if (cycling.velocity_rms_mps.isZero()) {
              e.counting = ctx.base->counting;
              return e;
            }
            if (!ctx.cache.count(key)) {
              runs::PulseCounting c = pulse_counting(*ctx.layout, *ctx.site, pulse, ctx.base->x_var,
                                                     ctx.base->noise_var.cwiseSqrt(), cycling);
              ctx.cache[key + " noise"] = c.noise_var;
              ctx.cache[key] = std::move(c.columns);
            }
            e.counting = runs::PulseCounting{ctx.cache[key], ctx.cache[key + " noise"].col(0)};
            return e;
          },
          {},
          "a test run with the vehicle held still, or f sampled faster than the sway periods"};
}

}  // namespace insmc::gap::candidates
