#pragma once
/// Raw samples of one sensor assembly (three gyros, three accelerometers)
/// from one or more recordings, on one sample grid, as the noise stage reads
/// them: a channel is one long vector, and each recording (a run) a segment
/// of it, so that no Allan window spans two recordings.
#include <array>
#include <span>
#include <string>
#include <vector>

#include "lib/imu/imu_samples.h"
#include "lib/noise/allan_variance.h"
#include "lib/noise/noise_terms.h"

namespace insmc::noise {

inline constexpr std::size_t kChannels = 6;
/// "gyro_x" ... "accel_z".
std::string channel_name(std::size_t c);
inline SensorKind channel_kind(std::size_t c) { return c < 3 ? SensorKind::kGyro : SensorKind::kAccelerometer; }

struct SensorRecording {
  double dt_s = 0;                  ///< sample spacing τ0 [s]
  std::vector<Segment> runs;        ///< one per recording, in input order
  std::vector<std::string> run_names;
  std::array<std::vector<double>, kChannels> channel;  ///< gyro x,y,z [rad/s], accel x,y,z [m/s²]
  std::size_t size() const { return channel[0].size(); }
};

/// The largest relative deviation of a sample spacing from the first
/// recording's median spacing that still counts as the same grid (logger
/// jitter); a larger step is refused with the file, the sample and the step.
inline constexpr double kMaxSpacingJitter = 0.1;

/// Puts the recordings on one grid: the median spacing of the first one is
/// τ0; every spacing of every recording must lie within ±kMaxSpacingJitter
/// of it (InputError naming the file, the time and the step otherwise: a gap
/// in a recording is a separate file, or is masked by the user beforehand).
SensorRecording make_recording(std::span<const ImuSamples> recordings);

}  // namespace insmc::noise
