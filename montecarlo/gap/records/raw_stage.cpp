#include "montecarlo/gap/records/raw_stage.h"

#include <algorithm>
#include <cstdlib>
#include <fmt/format.h>

#include "lib/noise/noise_budget.h"
#include "lib/noise/recording.h"

namespace insmc::mc {

std::optional<RawStage> raw_stage_from_header(const RecordHeader& header) {
  const std::string* on = header.find("imu.noise");
  if (!on || *on != "on") return std::nullopt;
  RawStage raw;
  for (std::size_t c = 0; c < noise::kChannels; ++c) {
    const std::string name = noise::channel_name(c);
    const std::string* eq = header.find("imu.noise." + name + ".equivalent_si");
    if (!eq) continue;
    RawChannel ch;
    ch.channel = name;
    ch.equivalent_si = std::strtod(eq->c_str(), nullptr);
    if (!(ch.equivalent_si >= 0)) continue;
    ch.ratio_to_bound = ch.equivalent_si / noise::table31_bound_si(noise::channel_kind(c));
    const std::string* warm = header.find("imu.noise." + name + ".warm_up_excluded");
    ch.warm_up_excluded = warm && *warm == "1";
    (c < 3 ? raw.gyro_ratio : raw.accel_ratio) = std::max(c < 3 ? raw.gyro_ratio : raw.accel_ratio, ch.ratio_to_bound);
    raw.channels.push_back(ch);
  }
  if (raw.channels.empty()) return std::nullopt;
  return raw;
}

std::string sensor_of_effect(const std::string& effect) {
  static const char* const kGyro[] = {"gyro_drift_instability", "angle_random_walk", "anisoelastic_drift"};
  static const char* const kAccel[] = {"accel_bias_instability", "velocity_random_walk", "scale_factor_nonlinearity"};
  bool gyro = false, accel = false;
  std::size_t p = 0;
  while (p <= effect.size()) {  // a class "a|b": every member
    const std::size_t q = std::min(effect.find('|', p), effect.size());
    const std::string one = effect.substr(p, q - p);
    for (const char* g : kGyro) gyro = gyro || one == g;
    for (const char* a : kAccel) accel = accel || one == a;
    p = q + 1;
  }
  return gyro == accel ? "" : gyro ? "gyro" : "accelerometer";
}

std::vector<std::string> raw_stage_statements(const RawStage& raw, const std::string& top) {
  std::vector<std::string> out;
  std::string warm;
  for (const RawChannel& c : raw.channels)
    if (c.warm_up_excluded) warm += (warm.empty() ? "" : ", ") + c.channel;
  out.push_back(fmt::format(
      "raw-sensor stage (import-imu, docs/noise.md): over one Schuler period the gyros' fitted noise is {:.3g}x and the "
      "accelerometers' {:.3g}x Table 3.1's bounds{}",
      raw.gyro_ratio, raw.accel_ratio, warm.empty() ? "" : fmt::format("; warm-up (first hour non-stationary) in {}", warm)));
  const std::string raw_sensor = raw.gyro_ratio >= raw.accel_ratio ? "gyro" : "accelerometer";
  const std::string nav_sensor = sensor_of_effect(top);
  if (!nav_sensor.empty() && nav_sensor != raw_sensor)
    out.push_back(fmt::format(
        "the navigation level and the raw stage disagree: the top candidate {} is an {} effect, while the raw outputs put "
        "the {}s furthest outside Table 3.1; in navigation residuals a gyro drift (a tilt, g times the integrated drift) "
        "and an accelerometer bias look alike, the raw outputs tell them apart",
        top, nav_sensor, raw_sensor));
  return out;
}

}  // namespace insmc::mc
