#include "lib/noise/noise_synthesis.h"

#include <cmath>
#include <numbers>

#include "lib/common/assert.h"

namespace insmc::noise {

NoiseSynthesizer::NoiseSynthesizer(const NoiseModel& model, double dt_s, const NormalSource& normals,
                                   std::uint64_t first_stream)
    : dt_s_(dt_s),
      white_(normals, first_stream),
      quantization_draws_(normals, first_stream + 1),
      walk_draws_(normals, first_stream + 2) {
  INSMC_ASSERT(dt_s > 0, "sample interval {}", dt_s);
  const double white_power = model[NoiseTerm::kWhiteRate];
  const double gm_power = model[NoiseTerm::kGaussMarkov], tc = model.correlation_time_s;
  if (gm_power > 0 && tc > 0) add_process(std::sqrt(gm_power), tc, normals, first_stream + 3);
  quantization_ = std::sqrt(model[NoiseTerm::kQuantization]);
  walk_step_ = std::sqrt(model[NoiseTerm::kRateRandomWalk] * dt_s);
  if (const double r = std::sqrt(model[NoiseTerm::kRateRamp]); r > 0)
    ramp_slope_ = NormalDraws(normals, first_stream + 4).next() < 0 ? -r : r;
  if (const double b2 = model[NoiseTerm::kBiasInstability]; b2 > 0) {
    // Half-decade spacing r = √10: Σ of Lorentzians 4σ²T_c/(1 + (2πfT_c)²)
    // ≈ (σ²/ln r)/f, so σ² = B² ln r / π gives B²/(π f).
    const double sigma = std::sqrt(b2 * std::log(std::sqrt(10.0)) / std::numbers::pi);
    std::uint64_t stream = first_stream + 5;
    for (double t = kFlickerMinTimeS; t <= kFlickerMaxTimeS * 1.0001; t *= std::sqrt(10.0))
      add_process(sigma, t, normals, stream++);
  }
  white_scale_ = std::sqrt(white_power / dt_s);
  if (quantization_ > 0) angle_ = quantization_ * quantization_draws_.next();
}

void NoiseSynthesizer::add_process(double sigma, double correlation_time_s, const NormalSource& normals,
                                   std::uint64_t stream) {
  Process p{.draws = NormalDraws(normals, stream)};
  const double tc = correlation_time_s;
  if (tc >= 50 * dt_s_) p.stride = static_cast<long>(tc / (20 * dt_s_));
  const double h = static_cast<double>(p.stride) * dt_s_, phi = std::exp(-h / tc);
  p.phi = phi;
  p.next_sd = sigma * std::sqrt(1 - phi * phi);
  p.value = sigma * p.draws.next();  // b from its stationary law
  if (p.stride == 1) {
    // The exact mean over a sample: with b' = φb + w₁ and ∫b = T_c(1 − φ)b + w₂,
    //   Var w₁ = σ²(1 − φ²), Var w₂ = 2σ²T_c[h − 2T_c(1 − φ) + T_c(1 − φ²)/2],
    //   Cov(w₁, w₂) = σ²T_c(1 − φ)²  (the Ornstein–Uhlenbeck process of (C.23)).
    const double v1 = sigma * sigma * (1 - phi * phi);
    const double v2 = 2 * sigma * sigma * tc * (h - 2 * tc * (1 - phi) + tc * (1 - phi * phi) / 2);
    const double c = sigma * sigma * tc * (1 - phi) * (1 - phi);
    p.mean_gain = tc * (1 - phi) / h;
    p.mean_common = c / std::sqrt(v1) / h;
    p.mean_own = std::sqrt(std::max(0.0, v2 - c * c / v1)) / h;
  }
  processes_.push_back(p);
}

double NoiseSynthesizer::next() {
  double y = walk_ + ramp_slope_ * static_cast<double>(k_) * dt_s_;
  if (white_scale_ > 0) y += white_scale_ * white_.next();
  if (quantization_ > 0) {
    const double next_angle = quantization_ * quantization_draws_.next();
    y += (next_angle - angle_) / dt_s_;
    angle_ = next_angle;
  }
  if (walk_step_ > 0) walk_ += walk_step_ * walk_draws_.next();
  for (Process& p : processes_) {
    if (p.stride == 1) {
      const double z1 = p.draws.next(), z2 = p.draws.next();
      y += p.mean_gain * p.value + p.mean_common * z1 + p.mean_own * z2;
      p.value = p.phi * p.value + p.next_sd * z1;
    } else {
      y += p.value;  // held between steps
      if (++p.countdown == p.stride) {
        p.countdown = 0;
        p.value = p.phi * p.value + p.next_sd * p.draws.next();
      }
    }
  }
  ++k_;
  return y;
}

}  // namespace insmc::noise
