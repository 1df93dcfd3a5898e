#pragma once
/// The bytes of a study's merged state (every output's statistics and the
/// kept values): what a checkpoint stores and MPI ranks exchange. Kept apart
/// from the engine so that the fuzz target of the checkpoint reader
/// (tests/fuzz) reads states as `run --resume` does.
#include <string>
#include <string_view>
#include <vector>

#include "montecarlo/study/aggregate/kept_samples.h"
#include "montecarlo/study/aggregate/output_stats.h"

namespace insmc::mc {

struct AccumulatorState {
  std::vector<OutputStats> outputs;
  KeptSamples kept;
};

std::string serialize_state(const std::vector<OutputStats>& outputs, const KeptSamples& kept);

/// Throws std::runtime_error on anything but a state serialize_state wrote
/// (wrong magic, truncated, trailing bytes, impossible counts); memory
/// follows the bytes given.
AccumulatorState deserialize_state(std::string_view bytes);

}  // namespace insmc::mc
