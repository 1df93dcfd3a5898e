// counter_kernels.h's loops built for AVX512 (this file alone is compiled with
// -mavx512f -O3: see montecarlo/CMakeLists.txt); called only when the CPU has it.
#include "montecarlo/study/kernels/counter_loops.h"
#include "montecarlo/study/kernels/instrument_kernels.h"

namespace insmc::mc::kernels {

#if defined(__AVX512F__)
void count_pulses_avx512(const PulseInterval& in, std::size_t n, double* counted, double* datum) {
  count_pulses_loop(in, n, counted, datum);
}
void read_positions_avx512(const PositionReadings& in, std::size_t n, double* datum) {
  read_positions_loop(in, n, datum);
}
#endif

}  // namespace insmc::mc::kernels
