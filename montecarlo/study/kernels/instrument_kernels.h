#pragma once
/// The per-instruction-set builds of counter_kernels.h's loops, each in its
/// own file compiled for its unit (defined only on x86-64 builds).
#include <cstddef>

#include "montecarlo/study/kernels/counter_kernels.h"

namespace insmc::mc::kernels {

void count_pulses_avx2(const PulseInterval& in, std::size_t n, double* counted, double* datum);
void read_positions_avx2(const PositionReadings& in, std::size_t n, double* datum);
void count_pulses_avx512(const PulseInterval& in, std::size_t n, double* counted, double* datum);
void read_positions_avx512(const PositionReadings& in, std::size_t n, double* datum);

}  // namespace insmc::mc::kernels
