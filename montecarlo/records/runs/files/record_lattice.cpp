#include "montecarlo/records/runs/files/record_lattice.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <set>

#include "lib/preflight/test_run.h"

namespace insmc::runs {
namespace {

constexpr int kMinValues = 20;
constexpr int kMinNonzero = 10;
constexpr int kMinDistinct = 3;

/// Whether every value is within tolerance × w of a multiple of w; the
/// multiples seen and the least-squares step.
struct Trial {
  bool fits = false;
  int distinct = 0;
  double step = 0.0;
};

/// `by_magnitude`: the values by increasing |v|. The base w is a spacing
/// between two printed values, off by their round-off, and n times that
/// grows with the multiple n: the step is refined as the multiples grow
/// (the least-squares step of the values seen so far), and every value is
/// then checked against the final one.
Trial try_step(const std::vector<double>& by_magnitude, double w, double tolerance) {
  Trial t;
  double nn = 0.0, nv = 0.0, step = w;
  for (double v : by_magnitude) {
    const double n = std::round(v / step);
    if (std::abs(v - n * step) > tolerance * step || std::abs(n) > 1e12) return t;
    nn += n * n;
    nv += n * v;
    if (nn > 0) step = nv / nn;
  }
  if (!(nn > 0)) return t;
  std::set<long long> multiples;
  int nonzero = 0;
  for (double v : by_magnitude) {
    const double n = std::round(v / step);
    if (std::abs(v - n * step) > tolerance * step) return t;
    multiples.insert(static_cast<long long>(n));
    nonzero += n != 0.0;
  }
  t.distinct = static_cast<int>(multiples.size());
  t.fits = nonzero >= kMinNonzero && t.distinct >= kMinDistinct;
  t.step = t.fits ? step : 0.0;
  return t;
}

/// The largest step w such that every value lies within `tolerance` × w of a
/// whole multiple of w, visiting at least three multiples and ten nonzero
/// ones (a smooth signal can sit near one multiple of some step; a
/// continuous one falls within ±1 % of a lattice point with probability
/// 0.02 per value, so 20 values fit by chance with probability 1e-34). The
/// steps tried are the smallest nonzero spacings of the sorted values
/// divided by 1–6.
LatticeFit fit_lattice(std::vector<double> values, double tolerance = 0.01) {
  LatticeFit fit;
  fit.values = static_cast<int>(values.size());
  if (fit.values < kMinValues) return fit;
  std::sort(values.begin(), values.end());
  std::vector<double> gaps;
  for (std::size_t i = 1; i < values.size(); ++i) gaps.push_back(values[i] - values[i - 1]);
  const double widest = *std::max_element(gaps.begin(), gaps.end());
  if (!(widest > 0)) return fit;  // all equal: no spacing to see
  // The step is the smallest spacing between distinct lattice points, or a
  // whole fraction of it when some multiples are unseen. Sets of bases: the
  // smallest spacings above the values' printing round-off (values exact to
  // the 17th digit, or printed to 9 digits or to the millimetre by another
  // writer: one lattice point then shows as a cluster of values that far
  // apart; a lattice visited densely) and above 2 % of the widest (one
  // lattice point seen twice with a small leftover, e.g. the nominal's in f).
  double largest = 0.0;
  for (double v : values) largest = std::max(largest, std::abs(v));
  std::vector<double> bases;
  for (const double floor : {1e-9 * largest, 1e-7 * largest, 1e-5 * largest, 1e-3 * largest, 0.02 * widest}) {
    std::vector<double> above;
    for (double g : gaps)
      if (g > floor) above.push_back(g);
    std::sort(above.begin(), above.end());
    above.resize(std::min<std::size_t>(above.size(), 5));
    bases.insert(bases.end(), above.begin(), above.end());
  }
  std::sort(bases.begin(), bases.end(), std::greater<>());
  std::vector<double> by_magnitude = values;
  std::sort(by_magnitude.begin(), by_magnitude.end(), [](double a, double b) { return std::abs(a) < std::abs(b); });
  fit.kind = LatticeFit::Kind::kContinuous;
  fit.finest_tried = bases.back() / 6;
  fit.coarsest_tried = bases.front();
  double best = 0.0;
  for (double base : bases)
    for (int k = 1; k <= 6; ++k) {
      const double w = base / k;
      if (w <= best * (1 + tolerance)) break;
      const Trial t = try_step(by_magnitude, w, tolerance);
      if (!t.fits) continue;
      best = w;
      fit.kind = LatticeFit::Kind::kLattice;
      fit.step = t.step;
      fit.distinct_multiples = t.distinct;
      break;  // a finer fraction of this base fits too; the largest is wanted
    }
  return fit;
}

/// Differences of `order` (1 or 2) of each run's consecutive counted
/// velocities u_k: windows τ apart (a recorder's jitter allowed). A dropped
/// record ends the stretch: a difference across it spans two windows, whose
/// leftover of the nominal increment (g at the site against the report's)
/// no longer cancels, and one such value off the lattice hid the pulses of
/// a whole file.
std::vector<double> counted_differences(const RecordFile& file, const ModelOptions& model, double tau, int order) {
  std::vector<double> values;
  for (const RecordRun& run : file.runs)
    for (int a = 0; a < 3; ++a) {
      double last_t = 0.0;
      std::vector<double> u;  // the current stretch of consecutive windows
      for (const RecordRow& row : run.rows) {
        if (row.phase != Phase::kTest || !row.f_mps2[static_cast<std::size_t>(a)] || row.t_s < tau * (1 - 1e-9))
          continue;
        if (!u.empty() && row.t_s - last_t > 1.5 * tau) u.clear();
        // The window of a stamp that jitters is the grid's: the nominal's
        // increment over it turns with the earth (ω_ie g τ per second of
        // stamp, 1 % of a 0.1 ft/s pulse at 50 ms off a 10-s grid).
        const double on_grid_t = std::round(row.t_s / tau) * tau;
        const double t = std::abs(row.t_s - on_grid_t) <= kMaxStampJitter * tau ? on_grid_t : row.t_s;
        u.push_back(*row.f_mps2[static_cast<std::size_t>(a)] * tau +
                    (nominal_velocity_increment(t, model) - nominal_velocity_increment(t - tau, model))[a]);
        last_t = row.t_s;
        const std::size_t n = u.size();
        if (order == 1 && n >= 2) values.push_back(u[n - 1] - u[n - 2]);
        if (order == 2 && n >= 3) values.push_back(u[n - 1] - 2 * u[n - 2] + u[n - 3]);
      }
    }
  return values;
}

}  // namespace

LatticeFit f_pulse_lattice(const RecordFile& file, const ModelOptions& model, double tau) {
  const LatticeFit first = fit_lattice(counted_differences(file, model, tau, 1));
  if (first.kind == LatticeFit::Kind::kLattice) return first;
  // The nominal increment added back is at the report's g; a recorder that
  // took off its own at the site's g_s (0.17 % less at 45°,
  // docs/truth-vs-models.md) leaves a difference between consecutive
  // windows growing as g ω_ie τ²: past 1 % of a pulse from τ ≈ 20-30 s. It
  // changes linearly over a few windows, so second differences cancel it
  // and stay whole multiples of the pulse.
  const LatticeFit second = fit_lattice(counted_differences(file, model, tau, 2));
  return second.kind == LatticeFit::Kind::kLattice ? second : first;
}

LatticeFit r_resolution_lattice(const RecordFile& file, const ModelOptions& model) {
  std::vector<double> values;
  for (const RecordRun& run : file.runs) {
    bool have = false;
    Vec3 first = Vec3::Zero();
    for (const RecordRow& row : run.rows) {
      // Test rows: every scheme's navigation moves or resets the position
      // computer, and its clock may differ from the true position's.
      if (row.phase != Phase::kTest || !row.r_ap_m) continue;
      const Vec3 v = *row.r_ap_m + true_position_ap(row.t_s, model);
      if (!have) {
        first = v;
        have = true;
        continue;
      }
      for (int a = 0; a < 3; ++a) values.push_back(v[a] - first[a]);
    }
  }
  return fit_lattice(std::move(values));
}

}  // namespace insmc::runs
