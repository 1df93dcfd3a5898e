// quantization: ΔV pulses of another weight than the model assumes, modelled
// by the counters themselves (pulse_counting.h), not by an added noise.
#include "montecarlo/records/gap/candidates/common.h"
#include "montecarlo/records/gap/candidates/definitions.h"

namespace insmc::gap::candidates {

Candidate quantization() {
  return {"quantization",
          "ΔV pulses of another weight than the model's: counting noise w²/(6τ²) in f, and in r the pulse phase and "
          "the slow sawtooth of the counters' velocity error (pulse_counting.h)",
          {searched("dv_pulse", Dimension::kVelocity, log_grid(0.02, 5, 1.0), 1e-6, 1.0,
                    "1e-6 to 1 m/s, the pulse weights `insmc simulate --dv-pulse` allows (lib/preflight/test_run.h)")},
          [](const LayoutContext& ctx, std::span<const double> p) {
            runs::Extension e;
            e.counting = pulse_counting(*ctx.layout, *ctx.site, p[0], ctx.base->x_var, ctx.base->noise_var.cwiseSqrt());
            return e;
          },
          {},
          "the recorder's pulse weight (header dv_pulse_mps) or f at a finer resolution"};
}

}  // namespace insmc::gap::candidates
