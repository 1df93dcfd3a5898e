#pragma once
// Implementation of integrate_schuler_ode (a template: the forcing is any
// callable t -> Sensitivity3).
#include <algorithm>
#include <cmath>

#include "lib/common/assert.h"

namespace insmc {

template <class Map, class Forcing>
std::vector<Map> integrate_schuler_maps(const Forcing& forcing, const Map& r0_map, const Map& v0_map,
                                        const std::vector<double>& times_s, double schuler_radps,
                                        double max_step_s, double t_start_s) {
  INSMC_ASSERT(max_step_s > 0, "max_step_s = {}", max_step_s);
  const double w2 = schuler_radps * schuler_radps;
  std::vector<Map> out;
  out.reserve(times_s.size());
  Map r = r0_map, v = v0_map;
  double t = t_start_s;
  for (double target : times_s) {
    INSMC_ASSERT(target >= t, "times must ascend: {} after {}", target, t);
    const double span = target - t;
    const int steps = span > 0 ? static_cast<int>(std::ceil(span / max_step_s - 1e-12)) : 0;
    const double h = steps > 0 ? span / steps : 0.0;
    for (int i = 0; i < steps; ++i) {
      // Classical RK4 on (r, v): ṙ = v, v̇ = −ω_s² r + u(t).
      const Map u0 = forcing(t), um = forcing(t + 0.5 * h), u1 = forcing(t + h);
      const Map k1r = v, k1v = -w2 * r + u0;
      const Map k2r = v + 0.5 * h * k1v, k2v = -w2 * (r + 0.5 * h * k1r) + um;
      const Map k3r = v + 0.5 * h * k2v, k3v = -w2 * (r + 0.5 * h * k2r) + um;
      const Map k4r = v + h * k3v, k4v = -w2 * (r + h * k3r) + u1;
      r += h / 6.0 * (k1r + 2 * k2r + 2 * k3r + k4r);
      v += h / 6.0 * (k1v + 2 * k2v + 2 * k3v + k4v);
      t += h;
    }
    t = target;
    out.push_back(r);
  }
  return out;
}

template <class Forcing>
std::vector<Sensitivity3> integrate_schuler_ode(const Forcing& forcing, const Sensitivity3& r0_map,
                                                const Sensitivity3& v0_map,
                                                const std::vector<double>& times_s,
                                                double schuler_radps, double max_step_s,
                                                double t_start_s) {
  return integrate_schuler_maps<Sensitivity3>(forcing, r0_map, v0_map, times_s, schuler_radps,
                                              max_step_s, t_start_s);
}

}  // namespace insmc
