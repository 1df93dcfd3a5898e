#include "lib/noise/noise_budget.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "lib/uncertainty/catalogue.h"
#include "lib/units/units.h"

namespace insmc::noise {

double schuler_period_s() { return 2 * std::numbers::pi / schuler_frequency_radps(); }

std::string table31_bound_text(SensorKind kind) {
  return kind == SensorKind::kGyro ? fmt::format("{:g} meru", table31_bound_si(kind) / kMeruToRadps)
                                   : fmt::format("{:g} mg", table31_bound_si(kind) / kMgToMps2);
}

double table31_bound_si(SensorKind kind) {
  if (kind == SensorKind::kGyro) return find_uncertainty("gyro_drift_x")->default_bound_si;
  // ∂f < 0.1 mg: its constant and per-alignment halves.
  return find_uncertainty("bias_change_const_x")->default_bound_si +
         find_uncertainty("bias_change_align_x")->default_bound_si;
}

double equivalent_constant(NoiseTerm t, double value_si, double tc_s) {
  const double ts = schuler_period_s();
  switch (t) {
    case NoiseTerm::kQuantization: return value_si / ts;
    case NoiseTerm::kWhiteRate: return value_si / std::sqrt(ts);
    case NoiseTerm::kBiasInstability: return value_si;
    case NoiseTerm::kRateRandomWalk: return value_si * std::sqrt(ts / 3);
    case NoiseTerm::kRateRamp: return value_si * ts;
    case NoiseTerm::kGaussMarkov: {
      const double x = tc_s / ts;
      return value_si * std::sqrt(std::max(0.0, 2 * x * (1 - x * (-std::expm1(-1 / x)))));
    }
  }
  return 0;
}

double equivalent_constant(const NoiseModel& model) {
  double rss = 0;
  for (NoiseTerm t : kAllNoiseTerms)
    if (model[t] > 0) {
      const double e = equivalent_constant(t, std::sqrt(model[t]), model.correlation_time_s);
      rss += e * e;
    }
  return std::sqrt(rss);
}

}  // namespace insmc::noise
