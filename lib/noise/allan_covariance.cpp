#include "lib/noise/allan_covariance.h"

#include <algorithm>
#include <cmath>

#include "lib/noise/noise_fit.h"

namespace insmc::noise {
namespace {

constexpr int kMaxLagPoints = 4001;

double model_structure(const NoiseModel& m, double s) {
  double d = 0;
  for (NoiseTerm t : kAllNoiseTerms)
    if (t != NoiseTerm::kRateRamp && m[t] > 0) d += m[t] * structure_shape(t, s, m.correlation_time_s);
  return d;  // the ramp is deterministic: it has no variance of its own
}

/// (N.3) at lag h (samples, may be fractional on the trapezoid grid).
double cross_covariance(const NoiseModel& m, double h, double a, double b, double dt) {
  static constexpr double c[3] = {1, -2, 1};
  double sum = 0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) sum += c[i] * c[j] * model_structure(m, (h + i * a - j * b) * dt);
  return -0.5 * sum;
}

/// Window pairs (k, l) with k − l = h, 0 ≤ k < na, 0 ≤ l < nb.
double pair_count(double h, double na, double nb) { return std::max(0.0, std::min(na, nb + h) - std::max(0.0, h)); }

}  // namespace

Eigen::MatrixXd allan_covariance(std::span<const AllanLevel> levels, double dt_s, const NoiseModel& model) {
  const auto J = static_cast<Eigen::Index>(levels.size());
  Eigen::MatrixXd cov = Eigen::MatrixXd::Zero(J, J);
  // How far the second differences stay correlated beyond their overlap:
  // Gauss–Markov over a few T_c, flicker (bias instability) over a few window lengths.
  const double gm_reach = model[NoiseTerm::kGaussMarkov] > 0 ? 10 * model.correlation_time_s / dt_s : 0;
  const bool flicker = model[NoiseTerm::kBiasInstability] > 0;
  for (Eigen::Index p = 0; p < J; ++p)
    for (Eigen::Index q = p; q < J; ++q) {
      const AllanLevel& la = levels[static_cast<std::size_t>(p)];
      const AllanLevel& lb = levels[static_cast<std::size_t>(q)];
      const double a = static_cast<double>(la.cluster), b = static_cast<double>(lb.cluster);
      // A rate ramp R gives every second difference the mean μ = R τ²; then
      // Cov(Δ_a², Δ_b²) = 2C² + 4 μ_a μ_b C.
      const double ramp = std::sqrt(model[NoiseTerm::kRateRamp]);
      const double mu_ab = ramp * la.tau_s * la.tau_s * ramp * lb.tau_s * lb.tau_s;
      double total = 0;
      // Segments: the same list for both levels where both have windows.
      for (std::size_t s = 0; s < lb.segment_samples.size(); ++s) {
        const double n = static_cast<double>(lb.segment_samples[s]);
        const double na = n + 1 - 2 * a, nb = n + 1 - 2 * b;
        if (na <= 0 || nb <= 0) continue;
        const double overlap = 2 * a + 2 * b;
        const double reach = std::min(std::max(overlap + gm_reach, flicker ? 8 * overlap : overlap), n);
        const double lo = -std::min(reach, nb), hi = std::min(reach, na);
        const double span = hi - lo;
        double sum = 0;
        if (span + 1 <= kMaxLagPoints) {
          for (double h = std::ceil(lo); h <= hi; h += 1) {
            const double cc = cross_covariance(model, h, a, b, dt_s);
            sum += pair_count(h, na, nb) * (2 * cc * cc + 4 * mu_ab * cc);
          }
        } else {
          const double step = span / (kMaxLagPoints - 1);
          for (int i = 0; i < kMaxLagPoints; ++i) {
            const double h = lo + step * i;
            const double cc = cross_covariance(model, h, a, b, dt_s);
            const double w = (i == 0 || i == kMaxLagPoints - 1) ? 0.5 : 1.0;
            sum += w * step * pair_count(h, na, nb) * (2 * cc * cc + 4 * mu_ab * cc);
          }
        }
        total += sum;
      }
      const double na_all = static_cast<double>(la.windows), nb_all = static_cast<double>(lb.windows);
      const double v = total / (4 * la.tau_s * la.tau_s * lb.tau_s * lb.tau_s * na_all * nb_all);  // (N.4)
      cov(p, q) = cov(q, p) = v;
    }
  return cov;
}

}  // namespace insmc::noise
