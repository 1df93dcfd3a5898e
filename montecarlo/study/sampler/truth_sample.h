#pragma once
/// One sample's draws for the truth level with a compensation scheme: x, the
/// realignment's fresh ζ_r, ∂f_r, (u)V and the pulse counters' phases, from
/// the same counter-based streams as the linear pipeline (system_pipeline.h),
/// so that a sample index means the same draws at every fidelity.
#include <cstdint>

#include "lib/compensation/extended_vector.h"
#include "lib/compensation/truth_compensation.h"
#include "montecarlo/study/sampler/sampler.h"

namespace insmc::mc {

TruthSchemeSample draw_truth_sample(const Sampler& sampler, std::uint64_t seed, std::uint64_t index,
                                    const UncertaintyVector& x);

}  // namespace insmc::mc
