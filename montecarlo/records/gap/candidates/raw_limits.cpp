#include "montecarlo/records/gap/candidates/raw_limits.h"

#include <algorithm>
#include <fmt/format.h>
#include <string_view>
#include <utility>

#include "lib/truth/effect.h"
#include "lib/units/quantity_display.h"

namespace insmc::gap {

namespace {

/// The raw sensor a parameter's limit is read from: the velocity
/// quantization is the accelerometers', the rest the effect's own sensor.
RawSensor limiting_sensor(const EffectInfo& info, RawSensorLimit limit) {
  return limit == RawSensorLimit::kVelocityQuantization ? RawSensor::kAccelerometer : info.sensor;
}

}  // namespace

std::string sensor_of_effect(const std::string& effect) {
  bool gyro = false, accel = false;
  std::size_t p = 0;
  while (p <= effect.size()) {  // a class "a|b": every member
    const std::size_t q = std::min(effect.find('|', p), effect.size());
    if (const auto kind = find_effect(std::string_view(effect).substr(p, q - p))) {
      gyro = gyro || kind->info().sensor == RawSensor::kGyro;
      accel = accel || kind->info().sensor == RawSensor::kAccelerometer;
    }
    p = q + 1;
  }
  return gyro == accel ? "" : gyro ? "gyro" : "accelerometer";
}

std::vector<Candidate> limit_candidates(const std::vector<Candidate>& candidates, const runs::RawStage& raw,
                                        std::vector<std::string>& statements) {
  std::vector<Candidate> out = candidates;
  for (Candidate& c : out) {
    const auto kind = find_effect(c.name);
    if (!kind) continue;
    const EffectInfo& info = kind->info();
    for (const EffectParameter& limited : info.parameters) {
      if (limited.raw_limit == RawSensorLimit::kNone) continue;
      const bool gyro = limiting_sensor(info, limited.raw_limit) == RawSensor::kGyro;
      double cap = -1;
      for (const runs::RawChannel& ch : raw.channels) {
        if ((ch.channel.rfind("gyro", 0) == 0) != gyro) continue;
        // The selected term's interval upper end, or (not selected) what the
        // Allan deviation allows it at most.
        const auto [upper, bound] =
            limited.raw_limit == RawSensorLimit::kWhiteNoise1h ? std::pair{ch.walk_1h_upper_si, ch.walk_1h_bound_si}
            : limited.raw_limit == RawSensorLimit::kBiasWander ? std::pair{ch.wander_upper_si, ch.wander_bound_si}
                                                              : std::pair{ch.quantization_upper_si, ch.quantization_bound_si};
        const double v = upper >= 0 ? upper : bound;
        cap = std::max(cap, v);
      }
      if (cap < 0) continue;  // the header states nothing for this sensor
      if (cap == 0) {         // the raw outputs of this sensor do not vary at all
        statements.push_back(fmt::format("{}: left out (the raw {} outputs show no noise at all)", c.name,
                                         gyro ? "gyro" : "accelerometer"));
        c.name.clear();
        break;
      }
      for (CandidateParameter& p : c.parameters) {
        if (p.name != limited.name) continue;
        std::vector<double> grid;
        for (double g : p.grid)
          if (g < cap) grid.push_back(g);
        grid.push_back(cap);
        p.grid = grid;
        p.upper_si = std::min(p.upper_si, cap);
        p.lower_si = std::min(p.lower_si, cap);
        const std::string limit = format_quantity_rounded(cap, p.dimension);
        c.description += fmt::format(" ({} limited by the raw stage to {})", p.name, limit);
        statements.push_back(fmt::format("{}: {} limited to the raw outputs' {} (the upper end of the raw "
                                         "stage's interval)",
                                         c.name, p.name, limit));
      }
    }
  }
  std::erase_if(out, [](const Candidate& c) { return c.name.empty(); });
  return out;
}

std::vector<std::string> raw_stage_statements(const runs::RawStage& raw, const std::string& top) {
  std::vector<std::string> out;
  std::string warm;
  for (const runs::RawChannel& c : raw.channels)
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

}  // namespace insmc::gap
