#pragma once
/// The raw-sensor noise stage (docs/noise.md): for each of the six channels
/// of a static recording, the overlapping Allan deviation with its
/// confidence intervals, the fitted noise terms with their intervals, and
/// the stationarity of the first part, the IEEE slope readings; for the
/// assembly, the masked disturbances (each cut from the sensor that felt it). Steps: mask disturbances → fit the rest of each run (after
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
#include "lib/noise/slope_readings.h"
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

struct ChannelNoise {
  std::string name;
  SensorKind kind{};
  StationarityTest stationarity;
  bool first_part_excluded = false;
  std::vector<AllanRow> allan;  ///< of the samples the fit used
  NoiseFit fit;
  SlopeReadings readings;       ///< IEEE Std 952's slope readings of the same levels
  bool stuck = false;           ///< the output never changes: no noise to measure
  double longest_stretch_s = 0; ///< the longest stretch of consecutive samples the fit used
};

struct NoiseAnalysis {
  double dt_s = 0;
  double alpha = 0.01, confidence = 0.95;  ///< the options the analysis ran with
  double used_s = 0;   ///< time every channel keeps (all runs, every masked interval out)
  DisturbanceMask mask;
  std::array<ChannelNoise, kChannels> channels;
};

NoiseAnalysis analyse_noise(const SensorRecording& rec, const NoiseOptions& options = {});

}  // namespace insmc::noise
