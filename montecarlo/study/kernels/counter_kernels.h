#pragma once
/// The test run's instruments over a block of samples (draw-major: one
/// value per sample, the samples contiguous), vectorised with the unit the
/// CPU has (the same choice as map_product.h). Each element is the same
/// expression as the scalar instruments of lib/preflight/instruments.h, in
/// the same order with the same roundings, so every kernel gives their bits.
#include <cstddef>

#include "montecarlo/study/kernels/map_product.h"

namespace insmc::mc {

/// One filter interval of a ΔV pulse counter (DeltaVCounter) for n samples:
/// the velocity it sees is nominal + error[s] (+ sway_now[s] − sway_start[s]
/// when sway_now is given); counted[s] holds the count at the interval's
/// start and is advanced; datum[s] = the interval's Δf error.
struct PulseInterval {
  const double* error;
  const double* sway_now;    ///< nullptr: no sway
  const double* sway_start;
  const double* phase01;     ///< the counter's starting remainder in pulses, [0, 1)
  double nominal_mps, increment_mps, pulse_mps, interval_s;
};
void count_pulses(ProductKernel kernel, const PulseInterval& in, std::size_t n, double* counted, double* datum);

/// The position computer's readings (PositionReadout) for n samples:
/// datum[s] = position_reading_error(truth, truth + r0[s] + error[s], q) − first[s];
/// with error == nullptr, datum[s] = position_reading_error(truth, truth + r0[s], q)
/// (the first reading itself).
struct PositionReadings {
  const double* r0;
  const double* error;  ///< nullptr: the first reading
  const double* first;  ///< the first readings (ignored with error == nullptr)
  double truth_m, resolution_m;
};
void read_positions(ProductKernel kernel, const PositionReadings& in, std::size_t n, double* datum);

}  // namespace insmc::mc
