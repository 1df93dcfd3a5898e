#include "montecarlo/study/kernels/map_product.h"

#include <algorithm>

#include "lib/common/assert.h"
#include "montecarlo/study/kernels/map_product_kernels.h"
#include "montecarlo/study/kernels/map_product_tiles.h"

namespace insmc::mc {

namespace {
// 2 × 2 samples by 4 columns (SSE2 registers on x86-64; what the compiler
// makes of 2-double vectors elsewhere).
void map_product_generic(ProductShape shape, const double* x, std::size_t ldx, const double* m, std::size_t ldm,
                         double* y, std::size_t ldy) {
  tiled_product<2, 2, 4>(shape.samples, shape.depth, shape.columns, x, ldx, m, ldm, y, ldy);
}
}  // namespace

bool product_kernel_available(ProductKernel kernel) {
  switch (kernel) {
    case ProductKernel::Generic: return true;
    case ProductKernel::Avx2:
#if defined(INSMC_PRODUCT_AVX2)
      return __builtin_cpu_supports("avx2");
#else
      return false;
#endif
    case ProductKernel::Avx512:
#if defined(INSMC_PRODUCT_AVX512)
      return __builtin_cpu_supports("avx512f");
#else
      return false;
#endif
  }
  return false;
}

ProductKernel best_product_kernel() {
  static const ProductKernel best = product_kernel_available(ProductKernel::Avx512) ? ProductKernel::Avx512
                                    : product_kernel_available(ProductKernel::Avx2) ? ProductKernel::Avx2
                                                                                     : ProductKernel::Generic;
  return best;
}

std::string_view product_kernel_name(ProductKernel kernel) {
  switch (kernel) {
    case ProductKernel::Generic: return "generic";
    case ProductKernel::Avx2: return "AVX2";
    case ProductKernel::Avx512: return "AVX-512";
  }
  return "?";
}

void map_product_with(ProductKernel kernel, ProductShape shape, const double* x, std::size_t ldx, const double* m,
                      std::size_t ldm, double* y, std::size_t ldy) {
  INSMC_ASSERT(product_kernel_available(kernel), "product kernel {} is not available on this CPU",
               product_kernel_name(kernel));
  INSMC_ASSERT(shape.depth >= 0 && shape.columns >= 0 && ldx >= shape.samples && ldy >= shape.samples &&
                   ldm >= static_cast<std::size_t>(shape.depth),
               "map_product: leading dimensions {}, {}, {} too small for {} samples of depth {}", ldx, ldm, ldy,
               shape.samples, shape.depth);
  if (shape.samples == 0 || shape.columns == 0) return;
  if (shape.depth == 0) {  // an empty sum: +0 (x and m may then be empty, even null)
    for (int c = 0; c < shape.columns; ++c)
      std::fill_n(y + static_cast<std::size_t>(c) * ldy, shape.samples, 0.0);
    return;
  }
  switch (kernel) {
    case ProductKernel::Generic: return map_product_generic(shape, x, ldx, m, ldm, y, ldy);
    case ProductKernel::Avx2:
#if defined(INSMC_PRODUCT_AVX2)
      return kernels::map_product_avx2(shape, x, ldx, m, ldm, y, ldy);
#else
      return;
#endif
    case ProductKernel::Avx512:
#if defined(INSMC_PRODUCT_AVX512)
      return kernels::map_product_avx512(shape, x, ldx, m, ldm, y, ldy);
#else
      return;
#endif
  }
}

void map_product(ProductShape shape, const double* x, std::size_t ldx, const double* m, std::size_t ldm, double* y,
                 std::size_t ldy) {
  map_product_with(best_product_kernel(), shape, x, ldx, m, ldm, y, ldy);
}

}  // namespace insmc::mc
