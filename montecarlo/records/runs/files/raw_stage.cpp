#include "montecarlo/records/runs/files/raw_stage.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fmt/format.h>

#include "lib/noise/noise_budget.h"
#include "lib/records/import_keys.h"
#include "lib/noise/recording.h"
#include "lib/units/units.h"

namespace insmc::runs {

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

}  // namespace insmc::runs
