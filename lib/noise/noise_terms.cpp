#include "lib/noise/noise_terms.h"

#include <cmath>
#include <numbers>

namespace insmc::noise {

std::string_view term_name(NoiseTerm t, SensorKind s) {
  const bool gyro = s == SensorKind::kGyro;
  switch (t) {
    case NoiseTerm::kQuantization: return "quantization";
    case NoiseTerm::kWhiteRate: return gyro ? "angle_random_walk" : "velocity_random_walk";
    case NoiseTerm::kBiasInstability: return "bias_instability";
    case NoiseTerm::kRateRandomWalk: return gyro ? "rate_random_walk" : "acceleration_random_walk";
    case NoiseTerm::kRateRamp: return "rate_ramp";
    case NoiseTerm::kGaussMarkov: return "gauss_markov";
  }
  return "";
}

std::string_view term_si_unit(NoiseTerm t, SensorKind s) {
  const bool gyro = s == SensorKind::kGyro;
  switch (t) {
    case NoiseTerm::kQuantization: return gyro ? "rad" : "m/s";
    case NoiseTerm::kWhiteRate: return gyro ? "rad/sqrt(s)" : "m/s/sqrt(s)";
    case NoiseTerm::kBiasInstability: return gyro ? "rad/s" : "m/s2";
    case NoiseTerm::kRateRandomWalk: return gyro ? "rad/s/sqrt(s)" : "m/s2/sqrt(s)";
    case NoiseTerm::kRateRamp: return gyro ? "rad/s2" : "m/s3";
    case NoiseTerm::kGaussMarkov: return gyro ? "rad/s" : "m/s2";
  }
  return "";
}

namespace {
/// 3 − 4e^{−x} + e^{−2x}, accurate for small x (≈ 2x − 2x³/3 + x⁴/2).
double gm_bracket(double x) {
  if (x < 1e-3) return 2 * x - 2 * x * x * x / 3 + x * x * x * x / 2;
  return 3 - 4 * std::exp(-x) + std::exp(-2 * x);
}
}  // namespace

double avar_shape(NoiseTerm t, double tau, double tc) {
  switch (t) {
    case NoiseTerm::kQuantization: return 3 / (tau * tau);                             // (C.9)
    case NoiseTerm::kWhiteRate: return 1 / tau;                                        // (C.12)
    case NoiseTerm::kBiasInstability: return 2 * std::numbers::ln2 / std::numbers::pi;  // (C.15)
    case NoiseTerm::kRateRandomWalk: return tau / 3;                                   // (C.18)
    case NoiseTerm::kRateRamp: return tau * tau / 2;                                   // (C.20)
    case NoiseTerm::kGaussMarkov: {
      // (4D(τ) − D(2τ)) / (2τ²) with D below; = 2T_c/τ at τ ≫ T_c, 2τ/(3T_c) at τ ≪ T_c.
      const double x = tau / tc;
      if (x < 1e-3) return 2 * tau / (3 * tc) * (1 - 3 * x / 4);
      return tc / (tau * tau) * (2 * tau - tc * gm_bracket(x));
    }
  }
  return 0;
}

double structure_shape(NoiseTerm t, double s, double tc) {
  s = std::abs(s);
  if (s == 0) return 0;
  switch (t) {
    case NoiseTerm::kQuantization: return 2;                                     // θ + white angle noise
    case NoiseTerm::kWhiteRate: return s;                                        // Brownian angle
    case NoiseTerm::kBiasInstability: return -s * s * std::log(s) / std::numbers::pi;  // flicker: 4D(τ)−D(2τ) = (4 ln 2/π) τ²
    case NoiseTerm::kRateRandomWalk: return -s * s * s / 6;                      // 4D(τ)−D(2τ) = (2/3) τ³
    case NoiseTerm::kRateRamp: return -s * s * s * s / 12;                       // deterministic ramp: Var(ȳ_B−ȳ_A) = R²s²
    case NoiseTerm::kGaussMarkov: {
      // 2σ²[T_c s − T_c²(1 − e^{−s/T_c})] = 2σ²T_c² (x − 1 + e^{−x}), x = s/T_c; the
      // series Σ_{k≥2} (−x)^k/k! below x = 0.5 (the closed form cancels there).
      const double x = s / tc;
      double bracket = 0;
      if (x < 0.5) {
        double term = x * x / 2;
        for (int k = 2; k < 30 && term != 0; ++k, term *= -x / k) bracket += term;
      } else {
        bracket = x + std::expm1(-x);
      }
      return 2 * tc * tc * bracket;
    }
  }
  return 0;
}

double mean_difference_shape(NoiseTerm t, double tau, double lag, double tc) {
  // (N.1)
  return (2 * structure_shape(t, tau, tc) - structure_shape(t, lag + tau, tc) - structure_shape(t, lag - tau, tc) +
          2 * structure_shape(t, lag, tc)) /
         (tau * tau);
}

int power_law_alpha(NoiseTerm t, double tau, double tc) {
  switch (t) {
    case NoiseTerm::kQuantization: return 2;
    case NoiseTerm::kWhiteRate: return 0;
    case NoiseTerm::kBiasInstability: return -1;
    case NoiseTerm::kRateRandomWalk:
    case NoiseTerm::kRateRamp: return -2;
    case NoiseTerm::kGaussMarkov: return tau < tc ? -2 : 0;
  }
  return 0;
}

}  // namespace insmc::noise
