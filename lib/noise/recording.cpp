#include "lib/noise/recording.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

#include "lib/common/input_error.h"

namespace insmc::noise {

std::string channel_name(std::size_t c) {
  static const char* const kNames[kChannels] = {"gyro_x", "gyro_y", "gyro_z", "accel_x", "accel_y", "accel_z"};
  return kNames[c];
}

SensorRecording make_recording(std::span<const ImuSamples> recordings) {
  SensorRecording r;
  if (recordings.empty()) throw InputError("--input", "(missing)", "give at least one IMU CSV file");
  std::vector<double> steps;
  const ImuSamples& first = recordings.front();
  for (std::size_t k = 1; k < first.size(); ++k) steps.push_back(first.t_s[k] - first.t_s[k - 1]);
  std::nth_element(steps.begin(), steps.begin() + static_cast<std::ptrdiff_t>(steps.size() / 2), steps.end());
  r.dt_s = steps[steps.size() / 2];
  for (const ImuSamples& s : recordings) {
    for (std::size_t k = 1; k < s.size(); ++k) {
      const double step = s.t_s[k] - s.t_s[k - 1];
      if (std::abs(step / r.dt_s - 1) > kMaxSpacingJitter)
        throw InputError(fmt::format("{}: sample {} (t = {:.6g} s)", s.source, k + 1, s.t_s[k]), fmt::format("step {:.6g} s", step),
                         fmt::format("the noise stage needs one sample grid: every step within ±{:g} % of {:.6g} s "
                                     "(split the recording at a gap into separate files; when the time stamps only "
                                     "jitter about a fixed rate, give --rate instead of the time column)",
                                     100 * kMaxSpacingJitter, r.dt_s));
    }
    Segment seg{r.size(), r.size() + s.size()};
    for (std::size_t k = 0; k < s.size(); ++k)
      for (int a = 0; a < 3; ++a) {
        r.channel[a].push_back(s.gyro_b_radps[k][a]);
        r.channel[3 + a].push_back(s.accel_b_mps2[k][a]);
      }
    r.runs.push_back(seg);
    r.run_names.push_back(s.source);
  }
  return r;
}

}  // namespace insmc::noise
