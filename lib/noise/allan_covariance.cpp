#include "lib/noise/allan_covariance.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <vector>

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

/// The lags h = first + i·grid, i = 0 … steps, of one pair of levels whose
/// cluster lengths are steps_a and steps_b grid steps.
struct LagGrid {
  const NoiseModel& model;
  double dt_s, first, grid;
  std::int64_t steps, steps_a, steps_b;
  double na, nb, mu_ab;
  bool trapezoid;  ///< the trapezoid rule (× grid, half weight at the ends); else the plain sum over whole lags
};

/// Σ_h w_h n_ab(h) (2 C_ab(h)² + 4 μ_a μ_b C_ab(h)), (N.3)–(N.4), with D
/// tabulated once over the grid's lags and offsets: (N.3) reads nine entries
/// of the table instead of evaluating D nine times per lag.
double grid_sum(const LagGrid& L, std::vector<double>& table) {
  const std::int64_t origin = -2 * L.steps_b;  // the table starts 2b before the first lag
  table.clear();
  for (std::int64_t t = origin; t <= L.steps + 2 * L.steps_a; ++t)
    table.push_back(model_structure(L.model, (L.first + static_cast<double>(t) * L.grid) * L.dt_s));
  static constexpr double c[3] = {1, -2, 1};
  double sum = 0;
  for (std::int64_t i = 0; i <= L.steps; ++i) {
    double cs = 0;
    for (int u = 0; u < 3; ++u)
      for (int v = 0; v < 3; ++v) cs += c[u] * c[v] * table[static_cast<std::size_t>(i + u * L.steps_a - v * L.steps_b - origin)];
    const double cc = -0.5 * cs, h = L.first + static_cast<double>(i) * L.grid;
    const double w = !L.trapezoid ? 1.0 : (i == 0 || i == L.steps ? 0.5 : 1.0) * L.grid;
    sum += w * pair_count(h, L.na, L.nb) * (2 * cc * cc + 4 * L.mu_ab * cc);
  }
  return sum;
}

}  // namespace

Eigen::MatrixXd allan_covariance(std::span<const AllanLevel> levels, double dt_s, const NoiseModel& model) {
  const auto J = static_cast<Eigen::Index>(levels.size());
  Eigen::MatrixXd cov = Eigen::MatrixXd::Zero(J, J);
  // How far the second differences stay correlated beyond their overlap:
  // Gauss–Markov over a few T_c, flicker (bias instability) over a few window lengths.
  const double gm_reach = model[NoiseTerm::kGaussMarkov] > 0 ? 10 * model.correlation_time_s / dt_s : 0;
  const bool flicker = model[NoiseTerm::kBiasInstability] > 0;
  std::vector<double> table;  // D at whole lags, per pair of levels
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
          const double first = std::ceil(lo);
          const auto steps = static_cast<std::int64_t>(std::floor(hi) - first);
          sum = grid_sum({model, dt_s, first, 1, steps, static_cast<std::int64_t>(a), static_cast<std::int64_t>(b), na, nb,
                          mu_ab, false},
                         table);
        } else {
          // The trapezoid on a grid g that divides both cluster lengths (so
          // D is tabulated once), at least as fine as kMaxLagPoints points;
          // the old even split of the span where no such grid is small enough.
          const double target = span / (kMaxLagPoints - 1);
          const auto whole = static_cast<double>(std::gcd(static_cast<std::int64_t>(a), static_cast<std::int64_t>(b)));
          const double k = std::ceil(whole / target), g = whole / k;
          const double points = std::ceil(span / g);
          if (points <= 4.0 * kMaxLagPoints) {
            sum = grid_sum({model, dt_s, lo, g, static_cast<std::int64_t>(points), static_cast<std::int64_t>(a / whole * k),
                            static_cast<std::int64_t>(b / whole * k), na, nb, mu_ab, true},
                           table);
          } else {
            const double step = span / (kMaxLagPoints - 1);
            for (int i = 0; i < kMaxLagPoints; ++i) {
              const double h = lo + step * i;
              const double cc = cross_covariance(model, h, a, b, dt_s);
              const double w = (i == 0 || i == kMaxLagPoints - 1) ? 0.5 : 1.0;
              sum += w * step * pair_count(h, na, nb) * (2 * cc * cc + 4 * mu_ab * cc);
            }
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
