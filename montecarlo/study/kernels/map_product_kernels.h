#pragma once
/// The per-instruction-set kernels behind map_product (map_product.h). Each
/// is defined in its own file compiled for its instruction set, and only
/// when the compiler targets x86-64 (INSMC_PRODUCT_AVX2 / INSMC_PRODUCT_AVX512
/// say which were built).
#include <cstddef>

#include "montecarlo/study/kernels/map_product.h"

namespace insmc::mc::kernels {

void map_product_avx2(ProductShape shape, const double* x, std::size_t ldx, const double* m, std::size_t ldm,
                      double* y, std::size_t ldy);
void map_product_avx512(ProductShape shape, const double* x, std::size_t ldx, const double* m, std::size_t ldm,
                        double* y, std::size_t ldy);

}  // namespace insmc::mc::kernels
