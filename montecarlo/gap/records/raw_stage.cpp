#include "montecarlo/gap/records/raw_stage.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fmt/format.h>

#include "lib/noise/noise_budget.h"
#include "lib/records/import_keys.h"
#include "lib/noise/recording.h"
#include "lib/units/units.h"

namespace insmc::mc {

std::optional<RawStage> raw_stage_from_header(const RecordHeader& header) {
  const std::string* on = header.find(import_keys::kNoise);
  if (!on || *on != "on") return std::nullopt;
  RawStage raw;
  for (std::size_t c = 0; c < noise::kChannels; ++c) {
    const std::string name = noise::channel_name(c);
    const std::string* eq = header.find(import_keys::noise_key(name, "equivalent_si"));
    if (!eq) continue;
    RawChannel ch;
    ch.channel = name;
    ch.equivalent_si = std::strtod(eq->c_str(), nullptr);
    if (!(ch.equivalent_si >= 0)) continue;
    ch.ratio_to_bound = ch.equivalent_si / noise::table31_bound_si(noise::channel_kind(c));
    const std::string* warm = header.find(import_keys::noise_key(name, "warm_up_excluded"));
    ch.warm_up_excluded = warm && *warm == "1";
    const noise::SensorKind kind = noise::channel_kind(c);
    auto number = [&](const std::string& suffix) {
      const std::string* v = header.find(import_keys::noise_key(name, suffix));
      const double x = v ? std::strtod(v->c_str(), nullptr) : -1.0;
      return std::isfinite(x) ? x : -1.0;
    };
    ch.walk_1h_bound_si = number("white_1h_bound_si");
    ch.wander_bound_si = number("wander_bound_si");
    ch.quantization_bound_si = number("quantization_bound_si");
    auto upper = [&](noise::NoiseTerm t) { return number(std::string(noise::term_name(t, kind)) + "_upper_si"); };
    for (const noise::NoiseTerm t : noise::kAllNoiseTerms) {
      const double v = number(std::string(noise::term_name(t, kind)) + "_si");
      if (v > 0) ch.model[t] = v * v;
    }
    ch.model.correlation_time_s = std::max(0.0, number("correlation_time_s"));
    const double root_hour = std::sqrt(kHourToS);
    if (const double n = upper(noise::NoiseTerm::kWhiteRate); n >= 0) ch.walk_1h_upper_si = n * root_hour;
    ch.quantization_upper_si = upper(noise::NoiseTerm::kQuantization);
    const double tc = ch.model.correlation_time_s;
    for (const double w : {upper(noise::NoiseTerm::kBiasInstability),
                           upper(noise::NoiseTerm::kRateRandomWalk) >= 0 ? upper(noise::NoiseTerm::kRateRandomWalk) * root_hour : -1.0,
                           upper(noise::NoiseTerm::kRateRamp) >= 0 ? upper(noise::NoiseTerm::kRateRamp) * kHourToS : -1.0,
                           upper(noise::NoiseTerm::kGaussMarkov) >= 0 && tc > 0
                               ? noise::equivalent_constant(noise::NoiseTerm::kGaussMarkov, upper(noise::NoiseTerm::kGaussMarkov), tc)
                               : -1.0})
      ch.wander_upper_si = std::max(ch.wander_upper_si, w);
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

std::vector<gap::Candidate> limit_candidates(const std::vector<gap::Candidate>& candidates, const RawStage& raw,
                                             std::vector<std::string>& statements) {
  enum class Kind { kWalk, kWander, kQuantization };
  struct Limit {
    const char* candidate;
    const char* parameter;
    bool gyro;
    Kind kind;
  };
  static const Limit kLimits[] = {{"angle_random_walk", "angle_1h", true, Kind::kWalk},
                                  {"gyro_drift_instability", "sigma", true, Kind::kWander},
                                  {"velocity_random_walk", "velocity_1h", false, Kind::kWalk},
                                  {"accel_bias_instability", "sigma", false, Kind::kWander},
                                  {"quantization", "dv_pulse", false, Kind::kQuantization}};
  std::vector<gap::Candidate> out = candidates;
  for (gap::Candidate& c : out)
    for (const Limit& l : kLimits) {
      if (c.name != l.candidate) continue;
      double cap = -1;
      for (const RawChannel& ch : raw.channels) {
        if ((ch.channel.rfind("gyro", 0) == 0) != l.gyro) continue;
        // The selected term's interval upper end, or (not selected) what the
        // Allan deviation allows it at most.
        const auto [upper, bound] = l.kind == Kind::kWalk     ? std::pair{ch.walk_1h_upper_si, ch.walk_1h_bound_si}
                                    : l.kind == Kind::kWander ? std::pair{ch.wander_upper_si, ch.wander_bound_si}
                                                              : std::pair{ch.quantization_upper_si, ch.quantization_bound_si};
        const double v = upper >= 0 ? upper : bound;
        cap = std::max(cap, v);
      }
      if (cap < 0) continue;  // the header states nothing for this sensor
      if (cap == 0) {         // the raw outputs of this sensor do not vary at all
        statements.push_back(fmt::format("{}: left out (the raw {} outputs show no noise at all)", c.name,
                                         l.gyro ? "gyro" : "accelerometer"));
        c.name.clear();
        break;
      }
      for (gap::CandidateParameter& p : c.parameters) {
        if (p.name != l.parameter) continue;
        std::vector<double> grid;
        for (double g : p.grid)
          if (g < cap) grid.push_back(g);
        grid.push_back(cap);
        p.grid = grid;
        p.upper_si = std::min(p.upper_si, cap);
        p.lower_si = std::min(p.lower_si, cap);
        c.description += fmt::format(" ({} limited by the raw stage to {:.3g} SI)", p.name, cap);
        statements.push_back(fmt::format("{}: {} limited to the raw outputs' {:.3g} (SI; the upper end of the raw "
                                         "stage's interval)",
                                         c.name, p.name, cap));
      }
    }
  std::erase_if(out, [](const gap::Candidate& c) { return c.name.empty(); });
  return out;
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
