#pragma once
/// The loop of row_quadratic_forms (quadratic_forms.h), compiled once per
/// vector unit: plain C++ left to the vectoriser, in an unnamed namespace so
/// that each file's copy stays its own (no Eigen here: a template built for
/// AVX2 must not stand in for the generic one at link time).
#include <algorithm>
#include <cstddef>

namespace insmc::runs {
namespace {

/// Rows in blocks of kBlock: the block's columns of A (d × kBlock values)
/// stay in the first-level cache while every pair (k, j ≤ k) passes over
/// them. Within a row the sum runs over k, and within k over j, in the same
/// order whatever the block, so every kernel gives the same bits.
constexpr std::size_t kBlock = 32;

/// One block of nb ≤ kBlock rows. With nb known when compiled (kFixed), t
/// and acc stay in vector registers across the pairs.
template <std::size_t kFixed>
inline void quadratic_forms_block(const double* a, std::size_t lda, std::size_t nb_runtime, std::size_t d,
                                  const double* m, std::size_t ldm, double* q) {
  const std::size_t nb = kFixed > 0 ? kFixed : nb_runtime;
  double t[kBlock], acc[kBlock];
  for (std::size_t b = 0; b < nb; ++b) acc[b] = 0.0;
  for (std::size_t k = 0; k < d; ++k) {
    const double* ak = a + k * lda;
    const double mkk = m[k * ldm + k];
    for (std::size_t b = 0; b < nb; ++b) t[b] = mkk * ak[b];
    for (std::size_t j = 0; j < k; ++j) {
      const double w = 2.0 * m[j * ldm + k];  // M(k, j), below the diagonal
      const double* aj = a + j * lda;
      for (std::size_t b = 0; b < nb; ++b) t[b] += w * aj[b];
    }
    for (std::size_t b = 0; b < nb; ++b) acc[b] += ak[b] * t[b];
  }
  for (std::size_t b = 0; b < nb; ++b) q[b] = acc[b];
}

[[maybe_unused]] void quadratic_forms_loop(const double* a, std::size_t lda, std::size_t rows, std::size_t d,
                                           const double* m, std::size_t ldm, double* q) {
  std::size_t r0 = 0;
  for (; r0 + kBlock <= rows; r0 += kBlock) quadratic_forms_block<kBlock>(a + r0, lda, kBlock, d, m, ldm, q + r0);
  // The rest in blocks of 16, 8 and 4 rows known when compiled (a block of
  // a size known only at run time takes twice as long per row; a run
  // model's rows come in groups, each with such a rest), then at most 3 rows.
  if (rows - r0 >= 16) quadratic_forms_block<16>(a + r0, lda, 16, d, m, ldm, q + r0), r0 += 16;
  if (rows - r0 >= 8) quadratic_forms_block<8>(a + r0, lda, 8, d, m, ldm, q + r0), r0 += 8;
  if (rows - r0 >= 4) quadratic_forms_block<4>(a + r0, lda, 4, d, m, ldm, q + r0), r0 += 4;
  if (r0 < rows) quadratic_forms_block<0>(a + r0, lda, rows - r0, d, m, ldm, q + r0);
}

/// Lanes of the Gram's sums over rows: row i adds to lane i mod kLanes, and
/// the lanes are added in their order at the end, so the vectoriser needs
/// no reordering of a sum and every kernel gives the same bits.
constexpr std::size_t kLanes = 8;

[[maybe_unused]] void weighted_gram_loop(const double* a, std::size_t lda, std::size_t rows, std::size_t d,
                                         const double* w, double* g, std::size_t ldg) {
  const std::size_t whole = rows - rows % kLanes;
  for (std::size_t k = 0; k < d; ++k) {
    const double* ak = a + k * lda;
    for (std::size_t j = k; j < d; ++j) {
      const double* aj = a + j * lda;
      double lane[kLanes] = {};
      for (std::size_t i = 0; i < whole; i += kLanes)
        for (std::size_t b = 0; b < kLanes; ++b) lane[b] += w[i + b] * ak[i + b] * aj[i + b];
      for (std::size_t i = whole; i < rows; ++i) lane[i - whole] += w[i] * ak[i] * aj[i];
      double sum = 0.0;
      for (std::size_t b = 0; b < kLanes; ++b) sum += lane[b];
      g[k * ldg + j] = sum;  // G(j, k), on or below the diagonal
    }
  }
}

}  // namespace
}  // namespace insmc::runs
