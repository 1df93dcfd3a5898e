#pragma once
/// The tiled loop of map_product (map_product.h), one template for every
/// vector width. Included only by the kernel files, each compiled for its
/// own instruction set: everything here has internal linkage (an anonymous
/// namespace), so no copy built for AVX-512 can be chosen by the linker for
/// code that runs on a CPU without it.
#include <cstddef>
#include <cstring>

namespace insmc::mc {
namespace {

/// A vector of kLanes doubles (GCC/Clang vector extension: SSE2, AVX2 or
/// AVX-512 registers by the file's target flags, scalar code elsewhere).
template <int kLanes>
struct VectorOf;
template <>
struct VectorOf<2> {
  typedef double Type __attribute__((vector_size(16)));
};
template <>
struct VectorOf<4> {
  typedef double Type __attribute__((vector_size(32)));
};
template <>
struct VectorOf<8> {
  typedef double Type __attribute__((vector_size(64)));
};

template <int kLanes>
struct Lanes {
  using Vector = typename VectorOf<kLanes>::Type;
  static Vector load(const double* p) {
    Vector v;
    std::memcpy(&v, p, sizeof v);
    return v;
  }
  static void store(double* p, Vector v) { std::memcpy(p, &v, sizeof v); }
  // a − (+0) is a, exactly, for every a (−0, ∞ and NaN included); written
  // so it compiles to one broadcast at -O2 and -O3 (a loop over the lanes
  // became masked inserts at -O3).
  static Vector splat(double a) { return a - Vector{}; }
};

/// kVectors × kLanes consecutive samples by kColumns output columns: the
/// accumulators stay in registers over the whole depth.
template <int kLanes, int kVectors, int kColumns>
inline void product_tile(const double* x, std::size_t ldx, int depth, const double* m, std::size_t ldm, double* y,
                         std::size_t ldy) {
  using L = Lanes<kLanes>;
  // Every loop over the tile is unrolled in full, so that the accumulators
  // are registers (a loop left rolled keeps them on the stack: 2.5x slower).
  typename L::Vector acc[kVectors][kColumns];
#pragma GCC unroll 16
  for (int v = 0; v < kVectors; ++v)
#pragma GCC unroll 16
    for (int c = 0; c < kColumns; ++c) acc[v][c] = L::splat(0.0);
  for (int k = 0; k < depth; ++k) {
    typename L::Vector xv[kVectors];
#pragma GCC unroll 16
    for (int v = 0; v < kVectors; ++v) xv[v] = L::load(x + static_cast<std::size_t>(k) * ldx + v * kLanes);
#pragma GCC unroll 16
    for (int c = 0; c < kColumns; ++c) {
      const typename L::Vector mv = L::splat(m[static_cast<std::size_t>(c) * ldm + static_cast<std::size_t>(k)]);
#pragma GCC unroll 16
      for (int v = 0; v < kVectors; ++v) acc[v][c] = acc[v][c] + xv[v] * mv;
    }
  }
#pragma GCC unroll 16
  for (int v = 0; v < kVectors; ++v)
#pragma GCC unroll 16
    for (int c = 0; c < kColumns; ++c) L::store(y + static_cast<std::size_t>(c) * ldy + v * kLanes, acc[v][c]);
}

/// The columns left after the full tiles (fewer than kColumns): one tile of
/// exactly that many.
template <int kLanes, int kVectors, int kColumns>
inline void remaining_columns(int left, const double* x, std::size_t ldx, int depth, const double* m, std::size_t ldm,
                              double* y, std::size_t ldy) {
  if constexpr (kColumns > 0) {
    if (left == kColumns) return product_tile<kLanes, kVectors, kColumns>(x, ldx, depth, m, ldm, y, ldy);
    remaining_columns<kLanes, kVectors, kColumns - 1>(left, x, ldx, depth, m, ldm, y, ldy);
  }
}

/// Samples [0, n) in tiles of kVectors × kLanes, then single vectors, then
/// the last samples one by one (the same sums, element by element).
template <int kLanes, int kVectors, int kColumns>
inline void tiled_product(std::size_t n, int depth, int columns, const double* x, std::size_t ldx, const double* m,
                          std::size_t ldm, double* y, std::size_t ldy) {
  constexpr std::size_t kTile = static_cast<std::size_t>(kLanes * kVectors);
  const auto all_columns = [&]<int kV>(std::size_t s) {
    int c = 0;
    for (; c + kColumns <= columns; c += kColumns)
      product_tile<kLanes, kV, kColumns>(x + s, ldx, depth, m + static_cast<std::size_t>(c) * ldm, ldm,
                                         y + static_cast<std::size_t>(c) * ldy + s, ldy);
    remaining_columns<kLanes, kV, kColumns - 1>(columns - c, x + s, ldx, depth, m + static_cast<std::size_t>(c) * ldm,
                                                ldm, y + static_cast<std::size_t>(c) * ldy + s, ldy);
  };
  std::size_t s = 0;
  for (; s + kTile <= n; s += kTile) all_columns.template operator()<kVectors>(s);
  for (; s + kLanes <= n; s += kLanes) all_columns.template operator()<1>(s);
  for (; s < n; ++s)
    for (int c = 0; c < columns; ++c) {
      double acc = 0.0;
      for (int k = 0; k < depth; ++k)
        acc = acc + x[static_cast<std::size_t>(k) * ldx + s] * m[static_cast<std::size_t>(c) * ldm + static_cast<std::size_t>(k)];
      y[static_cast<std::size_t>(c) * ldy + s] = acc;
    }
}

}  // namespace
}  // namespace insmc::mc
