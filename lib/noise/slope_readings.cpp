#include "lib/noise/slope_readings.h"

#include <cmath>
#include <numbers>
#include <vector>

namespace insmc::noise {
namespace {

/// Local log-log slope between rows j and j + 1.
double local_slope(std::span<const AllanRow> r, std::size_t j) {
  return std::log(r[j + 1].adev / r[j].adev) / std::log(r[j + 1].tau_s / r[j].tau_s);
}

bool near(double slope, double target) { return std::abs(slope - target) <= 0.25; }

/// The line of the given slope through rows [from, to] (least squares in
/// ln σ), its value at τ = at_s.
double line_at(std::span<const AllanRow> r, std::size_t from, std::size_t to, double slope, double at_s) {
  double sum = 0;
  for (std::size_t j = from; j <= to; ++j) sum += std::log(r[j].adev) - slope * std::log(r[j].tau_s / at_s);
  return std::exp(sum / static_cast<double>(to - from + 1));
}

}  // namespace

SlopeReadings read_slopes(std::span<const AllanRow> rows) {
  SlopeReadings out;
  for (const AllanRow& r : rows)
    if (!(r.adev > 0 && r.tau_s > 0)) return out;  // a stuck channel: nothing to read
  if (rows.size() < 2) return out;
  // The floor: the smallest deviation (C.15).
  std::size_t floor = 0;
  for (std::size_t j = 1; j < rows.size(); ++j)
    if (rows[j].adev < rows[floor].adev) floor = j;
  const double floor_factor = std::sqrt(2 * std::numbers::ln2 / std::numbers::pi);  // 0.664
  out.instability = {true, rows[floor].adev / floor_factor, rows[floor].tau_s, rows[floor].tau_s};

  // The −½ stretch nearest τ = 1 s (C.12): maximal runs of pairs on the slope.
  std::size_t best_from = 0, best_to = 0;
  double best_distance = INFINITY;
  for (std::size_t j = 0; j + 1 < rows.size();) {
    if (!near(local_slope(rows, j), -0.5)) {
      ++j;
      continue;
    }
    std::size_t k = j;
    while (k + 1 < rows.size() && near(local_slope(rows, k), -0.5)) ++k;
    // rows j..k lie on the slope; distance of τ = 1 s from the stretch in ln τ.
    const double lo = std::log(rows[j].tau_s), hi = std::log(rows[k].tau_s);
    const double distance = lo > 0 ? lo : hi < 0 ? -hi : 0.0;
    if (distance < best_distance) best_distance = distance, best_from = j, best_to = k;
    j = k;
  }
  // σ(1 s) on the line is N (σ² = N²/τ); σ(3 s) on the +½ line is K (σ² = K²τ/3).
  if (std::isfinite(best_distance))
    out.white = {true, line_at(rows, best_from, best_to, -0.5, 1.0), rows[best_from].tau_s,
                 rows[best_to].tau_s};

  // The +½ stretch beyond the floor (C.18): the levels from the first pair
  // after the floor on the slope to the end, every pair on it, rising beyond
  // the levels' scatter.
  for (std::size_t j = floor; j + 1 < rows.size(); ++j) {
    if (!near(local_slope(rows, j), 0.5)) continue;
    std::size_t k = j;
    while (k + 1 < rows.size() && near(local_slope(rows, k), 0.5)) ++k;
    if (k == rows.size() - 1 && rows[k].lower > rows[floor].upper)
      out.walk = {true, line_at(rows, j, k, 0.5, 3.0), rows[j].tau_s, rows[k].tau_s};
    break;
  }
  return out;
}

}  // namespace insmc::noise
