#pragma once
/// The block product of the study's linear maps, y = xᵀ M, with the widest
/// vector unit the CPU has, chosen at run time (the default build assumes
/// no more than x86-64's SSE2, so the binary stays portable).
///
/// Every kernel computes each element as the same sum in the same order,
///   y[r·ldy + s] = ((0 + x[0·ldx + s]·m[r·ldm + 0]) + x[1·ldx + s]·m[r·ldm + 1]) + …
/// (k ascending, a rounded product then a rounded sum, never a fused
/// multiply–add: the project builds with -ffp-contract=off), so the result
/// is the same bits on every CPU, and each sample's values depend on that
/// sample alone (not on its place in the block or on the block's size).
/// It is also the order in which Eigen 3.4 forms xᵀ·M, which the engine
/// used before, for every sample of a whole block (checked bit for bit in
/// tests/unit/montecarlo/study/kernels/map_product_test.cpp); Eigen summed the
/// last sample of an odd-sized block in another order (two interleaved
/// partial sums), so such a block's last sample may differ in the last bit.
///
/// Layouts: x is draw-major (x[k·ldx + s]: value k of sample s, the samples
/// of one value contiguous); m holds the map's columns (m[r·ldm + k]: row k
/// of output column r); y is sample-contiguous per output column.
#include <cstddef>
#include <string_view>

namespace insmc::mc {

enum class ProductKernel { Generic, Avx2, Avx512 };

struct ProductShape {
  std::size_t samples;  ///< n
  int depth;            ///< values per sample (the map's rows)
  int columns;          ///< the map's columns (outputs per sample)
};

/// y = xᵀ M for `shape`, by `kernel` (which must be available).
void map_product_with(ProductKernel kernel, ProductShape shape, const double* x, std::size_t ldx, const double* m,
                      std::size_t ldm, double* y, std::size_t ldy);

/// The same with the fastest kernel of this CPU.
void map_product(ProductShape shape, const double* x, std::size_t ldx, const double* m, std::size_t ldm, double* y,
                 std::size_t ldy);

bool product_kernel_available(ProductKernel kernel);
/// AVX-512 if the CPU has AVX-512F, else AVX2, else the generic kernel.
ProductKernel best_product_kernel();
std::string_view product_kernel_name(ProductKernel kernel);

}  // namespace insmc::mc
