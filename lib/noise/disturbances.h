#pragma once
/// Masking of disturbances (a bump, handling, a door slammed) in static
/// recordings before the noise analysis (docs/noise.md §4). The samples are
/// cut into blocks of max(1 s, 10 samples); a block is disturbed when, in
/// any channel,
/// - the log of its sample variance lies more than z_{1−α'} robust standard
///   deviations above the channel's median log variance (the spread measured
///   as 1.4826 × the median absolute departure: real noise is quantized and
///   heavy tailed, so χ²(n−1) would understate it); or
/// - its mean departs from the running median of the 31 blocks around it by
///   more than z_{1−α'/2} robust standard deviations (1.4826 × the median
///   absolute departure of the channel),
/// with α' = α / (blocks × channels) (Bonferroni: a clean recording has
/// probability ≤ α of losing any block). A disturbed block and one block on
/// each side are masked in every channel.
#include <string>
#include <vector>

#include "lib/noise/recording.h"

namespace insmc::noise {

struct MaskedInterval {
  std::size_t run = 0;            ///< index into SensorRecording::runs
  double start_s = 0, end_s = 0;  ///< from the start of the run
  std::string channels;           ///< the channels that flagged it, e.g. "gyro_x,accel_z"
  std::string test;               ///< "variance", "mean" or both
  double excess = 0;              ///< largest statistic as a multiple of its threshold
};

struct DisturbanceMask {
  double block_s = 0;
  std::vector<MaskedInterval> intervals;
  std::vector<Segment> kept;      ///< the runs with the masked intervals cut out
  std::size_t masked_samples = 0;
};

/// Finds the disturbed blocks at family-wise false-alarm probability alpha.
DisturbanceMask find_disturbances(const SensorRecording& rec, double alpha);
/// No masking: every run kept whole.
DisturbanceMask no_mask(const SensorRecording& rec);

}  // namespace insmc::noise
