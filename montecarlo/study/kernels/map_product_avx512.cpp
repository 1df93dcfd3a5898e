// map_product's AVX-512 kernel. This file alone is compiled with -mavx512f
// (see montecarlo/CMakeLists.txt); it is called only when the CPU has
// AVX-512F.
#include "montecarlo/study/kernels/map_product_kernels.h"
#include "montecarlo/study/kernels/map_product_tiles.h"

namespace insmc::mc::kernels {

#if defined(__AVX512F__)
// 2 × 8 samples by 6 columns: 12 accumulators of the 32 zmm registers.
void map_product_avx512(ProductShape shape, const double* x, std::size_t ldx, const double* m, std::size_t ldm,
                        double* y, std::size_t ldy) {
  tiled_product<8, 2, 6>(shape.samples, shape.depth, shape.columns, x, ldx, m, ldm, y, ldy);
}
#endif

}  // namespace insmc::mc::kernels
