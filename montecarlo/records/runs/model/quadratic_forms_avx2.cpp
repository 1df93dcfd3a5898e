// row_quadratic_forms' AVX2 kernel (quadratic_forms.h). This file alone is
// compiled with -mavx2 and without contraction into fused multiply-adds
// (montecarlo/records/CMakeLists.txt): four rows per instruction, each
// rounded as the generic kernel rounds it. Called only when the CPU has AVX2.
#include "montecarlo/records/runs/model/quadratic_forms_loop.h"

namespace insmc::runs::kernels {

#if defined(__AVX2__)
void row_quadratic_forms_avx2(const double* a, std::size_t lda, std::size_t rows, std::size_t d, const double* m,
                              std::size_t ldm, double* q) {
  quadratic_forms_loop(a, lda, rows, d, m, ldm, q);
}

void weighted_gram_avx2(const double* a, std::size_t lda, std::size_t rows, std::size_t d, const double* w, double* g,
                        std::size_t ldg) {
  weighted_gram_loop(a, lda, rows, d, w, g, ldg);
}
#endif

}  // namespace insmc::runs::kernels
