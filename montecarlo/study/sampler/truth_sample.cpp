#include "montecarlo/study/sampler/truth_sample.h"

#include <iterator>

#include "montecarlo/study/random/philox.h"

namespace insmc::mc {

TruthSchemeSample draw_truth_sample(const Sampler& sampler, std::uint64_t seed, std::uint64_t index,
                                    const UncertaintyVector& x) {
  constexpr int kRealignDraws = static_cast<int>(std::size(kRealignedSlots));
  // PulsePhase stream: ΔV counters at switch-over (3), torquer pulse counters
  // (3), alignment-phase ΔV counters (3) — the pipeline's order.
  double phase[9], fresh[kRealignDraws];
  fill_uniform01(seed, Stream::PulsePhase, index, 9, 1, phase);
  fill_uniform01(seed, Stream::Realignment, index, kRealignDraws, 1, fresh);
  TruthSchemeSample sample;
  sample.x = x;
  sample.realigned_x = x;
  for (int i = 0; i < kRealignDraws; ++i)
    sample.realigned_x[kRealignedSlots[i].x_index] = sampler.transform_one(kRealignedSlots[i].x_index, fresh[i]);
  sample.pulse_phase = Vec3(phase[0] - 0.5, phase[1] - 0.5, phase[2] - 0.5);
  sample.torquer_phase01 = Vec3(phase[3], phase[4], phase[5]);
  sample.align_pulse_phase01 = Vec3(phase[6], phase[7], phase[8]);
  return sample;
}

}  // namespace insmc::mc
