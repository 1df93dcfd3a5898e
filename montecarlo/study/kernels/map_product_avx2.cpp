// map_product's AVX2 kernel. This file alone is compiled with -mavx2 (see
// montecarlo/CMakeLists.txt); it is called only when the CPU has AVX2.
#include "montecarlo/study/kernels/map_product_kernels.h"
#include "montecarlo/study/kernels/map_product_tiles.h"

namespace insmc::mc::kernels {

#if defined(__AVX2__)
// 2 × 4 samples by 4 columns: 8 accumulators of the 16 ymm registers.
void map_product_avx2(ProductShape shape, const double* x, std::size_t ldx, const double* m, std::size_t ldm,
                      double* y, std::size_t ldy) {
  tiled_product<4, 2, 4>(shape.samples, shape.depth, shape.columns, x, ldx, m, ldm, y, ldy);
}
#endif

}  // namespace insmc::mc::kernels
