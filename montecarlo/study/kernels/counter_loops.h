#pragma once
/// The loops of counter_kernels.h, one template for every instruction set:
/// each kernel file includes it and is compiled for its own unit (see
/// map_product_tiles.h for why everything here has internal linkage). The
/// loops are plain, branch-free scalar code that the compiler vectorises
/// (those files build with -ftree-vectorize); round() is written out from
/// trunc() so that it vectorises too.
#include <cmath>
#include <cstddef>

#include "montecarlo/study/kernels/counter_kernels.h"

namespace insmc::mc {
namespace {

/// std::round (half away from zero), exactly: x − trunc(x) is exact, and
/// trunc(x) ± 1 is exact for every |x| below 2^52 (above, x is an integer
/// and the difference 0); NaN and ±∞ pass through, −0 stays −0.
inline double round_half_away(double x) {
  const double t = std::trunc(x);
  return std::fabs(x - t) >= 0.5 ? t + std::copysign(1.0, x) : t;
}

/// at_resolution (lib/preflight/observables.h) with the rounding above.
inline double at_resolution_vectorisable(double value, double q) {
  return q > 0 ? q * round_half_away(value / q) : value;
}

inline void count_pulses_loop(const PulseInterval& in, std::size_t n, double* __restrict counted,
                              double* __restrict datum) {
  const double* __restrict error = in.error;
  const double* __restrict phase = in.phase01;
  const double nominal = in.nominal_mps, increment = in.increment_mps, dv = in.pulse_mps, tau = in.interval_s;
  const bool pulses = dv > 0;
  const auto step = [&](std::size_t s, double v) {
    const double now = pulses ? dv * std::floor((v + phase[s] * dv) / dv) : v;
    datum[s] = (now - counted[s] - increment) / tau;
    counted[s] = now;
  };
  if (in.sway_now != nullptr) {
    const double* __restrict sway_now = in.sway_now;
    const double* __restrict sway_start = in.sway_start;
    for (std::size_t s = 0; s < n; ++s) step(s, nominal + error[s] + sway_now[s] - sway_start[s]);
  } else {
    for (std::size_t s = 0; s < n; ++s) step(s, nominal + error[s]);
  }
}

inline void read_positions_loop(const PositionReadings& in, std::size_t n, double* __restrict datum) {
  const double* __restrict r0 = in.r0;
  const double truth = in.truth_m, q = in.resolution_m;
  if (in.error == nullptr) {
    for (std::size_t s = 0; s < n; ++s) datum[s] = at_resolution_vectorisable(truth + r0[s], q) - truth;
    return;
  }
  const double* __restrict error = in.error;
  const double* __restrict first = in.first;
  for (std::size_t s = 0; s < n; ++s)
    datum[s] = (at_resolution_vectorisable(truth + r0[s] + error[s], q) - truth) - first[s];
}

}  // namespace
}  // namespace insmc::mc
