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
/// each side are masked in the channels of the sensor that flagged it (the
/// three gyros, or the three accelerometers): a bump that only the
/// accelerometers felt costs the gyros nothing.
#include <array>
#include <string>
#include <vector>

#include "lib/noise/recording.h"

namespace insmc::noise {

struct MaskedInterval {
  std::size_t run = 0;            ///< index into SensorRecording::runs
  double start_s = 0, end_s = 0;  ///< from the start of the run
  std::string channels;           ///< the channels that flagged it, e.g. "gyro_x,accel_z"
  std::string test;               ///< "variance", "mean" or both
  std::string sensors;            ///< the sensors it is cut from: "gyros", "accelerometers" or both
  double excess = 0;              ///< largest statistic as a multiple of its threshold
};

struct DisturbanceMask {
  double block_s = 0;
  std::vector<MaskedInterval> intervals;
  std::vector<Segment> kept;      ///< the runs with every masked interval cut out (all channels)
  std::size_t masked_samples = 0;
  /// Per sensor (SensorKind: gyros, accelerometers): the runs with that
  /// sensor's own masked blocks cut out, and how many samples it lost.
  std::array<std::vector<Segment>, 2> kept_by_sensor;
  std::array<std::size_t, 2> masked_by_sensor{};
  const std::vector<Segment>& kept_for(SensorKind kind) const { return kept_by_sensor[static_cast<std::size_t>(kind)]; }
};

/// Finds the disturbed blocks at family-wise false-alarm probability alpha.
DisturbanceMask find_disturbances(const SensorRecording& rec, double alpha);
/// No masking: every run kept whole.
DisturbanceMask no_mask(const SensorRecording& rec);

}  // namespace insmc::noise
