#pragma once
/// The raw-sensor noise stage (docs/noise.md): for each of the six channels
/// of a static recording, the overlapping Allan deviation with its
/// confidence intervals, the fitted noise terms with their intervals, and
/// the stationarity of the first part; for the assembly, the masked
/// disturbances. Steps: mask disturbances → fit the rest of each run (after
/// the first part) → test the first part against it → if it is like the
/// rest, fit everything kept; if not, leave the first part out and say so.
#include <array>
#include <vector>

#include "lib/noise/allan_variance.h"
#include "lib/noise/disturbances.h"
#include "lib/noise/noise_fit.h"
#include <functional>
#include <string_view>

#include "lib/noise/recording.h"
#include "lib/noise/stationarity.h"

namespace insmc::noise {

struct NoiseOptions {
  double alpha = 0.01;          ///< family-wise level of masking, stationarity and term selection
  double confidence = 0.95;     ///< of every interval
  double first_part_s = 3600;   ///< the warm-up tested against the rest (shortened to half the longest run); 0: no test
  bool mask = true;
  /// Told each stage as it starts: the disturbance mask (done 0), then each
  /// channel (done = channels finished, of kChannels).
  std::function<void(std::string_view stage, std::size_t done, std::size_t total)> progress;
};

struct AllanRow {
  double tau_s = 0, adev = 0, lower = 0, upper = 0, edf = 0, model_adev = 0;
  std::size_t windows = 0;
};

struct ChannelNoise {
  std::string name;
  SensorKind kind{};
  StationarityTest stationarity;
  bool first_part_excluded = false;
  std::vector<AllanRow> allan;  ///< of the samples the fit used
  NoiseFit fit;
};

struct NoiseAnalysis {
  double dt_s = 0;
  double used_s = 0;   ///< time the fit of a stationary channel uses (all runs, masked samples out)
  DisturbanceMask mask;
  std::array<ChannelNoise, kChannels> channels;
};

NoiseAnalysis analyse_noise(const SensorRecording& rec, const NoiseOptions& options = {});

}  // namespace insmc::noise
