#include "montecarlo/study/kernels/counter_kernels.h"

#include "lib/common/assert.h"
#include "montecarlo/study/kernels/counter_loops.h"
#include "montecarlo/study/kernels/instrument_kernels.h"

namespace insmc::mc {

void count_pulses(ProductKernel kernel, const PulseInterval& in, std::size_t n, double* counted, double* datum) {
  INSMC_ASSERT(product_kernel_available(kernel), "kernel {} is not available on this CPU", product_kernel_name(kernel));
  switch (kernel) {
    case ProductKernel::Generic: return count_pulses_loop(in, n, counted, datum);
    case ProductKernel::Avx2:
#if defined(INSMC_PRODUCT_AVX2)
      return kernels::count_pulses_avx2(in, n, counted, datum);
#else
      return;
#endif
    case ProductKernel::Avx512:
#if defined(INSMC_PRODUCT_AVX512)
      return kernels::count_pulses_avx512(in, n, counted, datum);
#else
      return;
#endif
  }
}

void read_positions(ProductKernel kernel, const PositionReadings& in, std::size_t n, double* datum) {
  INSMC_ASSERT(product_kernel_available(kernel), "kernel {} is not available on this CPU", product_kernel_name(kernel));
  switch (kernel) {
    case ProductKernel::Generic: return read_positions_loop(in, n, datum);
    case ProductKernel::Avx2:
#if defined(INSMC_PRODUCT_AVX2)
      return kernels::read_positions_avx2(in, n, datum);
#else
      return;
#endif
    case ProductKernel::Avx512:
#if defined(INSMC_PRODUCT_AVX512)
      return kernels::read_positions_avx512(in, n, datum);
#else
      return;
#endif
  }
}

}  // namespace insmc::mc
