#include "montecarlo/records/gap/fit/subgrid.h"

#include <cmath>
#include <limits>

namespace insmc::gap {

double parabola_vertex(const double (&x)[3], const double (&y)[3]) {
  const double a = (x[1] - x[0]) * (y[1] - y[2]), b = (x[1] - x[2]) * (y[1] - y[0]);
  const double den = a - b;
  // Convex with its least at the middle point: y[1] below the chord.
  const double chord = y[0] + (y[2] - y[0]) * (x[1] - x[0]) / (x[2] - x[0]);
  if (!(den != 0.0) || !(y[1] < chord) || !std::isfinite(den)) return x[1];
  const double v = x[1] - 0.5 * ((x[1] - x[0]) * a - (x[1] - x[2]) * b) / den;
  return std::isfinite(v) ? v : x[1];
}

std::vector<double> subgrid_values(const Candidate& c, const RunsUnderChoice& under,
                                   const Choice& best, const NullCalibration& m0) {
  std::vector<double> values = parameter_values(c, best);
  // Grid index = Σ index_i × stride_i, the last searched parameter fastest (Candidate::grid_point).
  int stride = 1;
  for (std::size_t i = c.parameters.size(); i-- > 0;) {
    const CandidateParameter& par = c.parameters[i];
    if (par.amplitude) continue;
    const int n = static_cast<int>(par.grid.size());
    const int at = (best.grid / stride) % n;
    const int here_stride = stride;
    stride *= n;
    if (at == 0 || at == n - 1) continue;
    // The nearest point on each side that the search evaluated, and G there
    // (each G once: for an amplitude candidate it is a least-squares fit).
    const auto gap_at = [&](int j) { return under.gap_at(best.grid + (j - at) * here_stride, m0); };
    const auto nearest = [&](int j, int step, int end, double& g) {
      for (g = gap_at(j); !std::isfinite(g) && j != end; g = gap_at(j)) j += step;
      return j;
    };
    double g[3];
    const int lo = nearest(at - 1, -1, 0, g[0]);
    // A grid's 0 is a limit of its own (no effect, or a random walk where
    // a correlation time is searched), not a point on the scale: no
    // refinement across it.
    if (!(par.grid[static_cast<std::size_t>(lo)] > 0) || !std::isfinite(g[0])) continue;
    const int hi = nearest(at + 1, 1, n - 1, g[2]);
    if (!std::isfinite(g[2])) continue;
    g[1] = gap_at(at);
    const double v[3] = {par.grid[static_cast<std::size_t>(lo)], par.grid[static_cast<std::size_t>(at)],
                         par.grid[static_cast<std::size_t>(hi)]};
    double x[3], y[3];
    for (int k = 0; k < 3; ++k) x[k] = std::log(v[k]), y[k] = g[k] * g[k];
    values[i] = std::exp(parabola_vertex(x, y));
  }
  return values;
}

}  // namespace insmc::gap
