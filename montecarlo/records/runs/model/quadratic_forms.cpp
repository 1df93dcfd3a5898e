#include "montecarlo/records/runs/model/quadratic_forms.h"

#include "lib/common/assert.h"
#include "montecarlo/records/runs/model/quadratic_forms_loop.h"

namespace insmc::runs {

namespace kernels {
#if defined(INSMC_QUADRATIC_FORMS_AVX2)
void row_quadratic_forms_avx2(const double* a, std::size_t lda, std::size_t rows, std::size_t d, const double* m,
                              std::size_t ldm, double* q);
void weighted_gram_avx2(const double* a, std::size_t lda, std::size_t rows, std::size_t d, const double* w, double* g,
                        std::size_t ldg);
#endif
}  // namespace kernels

bool quadratic_forms_avx2_available() {
#if defined(INSMC_QUADRATIC_FORMS_AVX2)
  static const bool available = __builtin_cpu_supports("avx2");
  return available;
#else
  return false;
#endif
}

void row_quadratic_forms_generic(const double* a, std::size_t lda, std::size_t rows, std::size_t d, const double* m,
                                 std::size_t ldm, double* q) {
  quadratic_forms_loop(a, lda, rows, d, m, ldm, q);
}

void row_quadratic_forms(const double* a, std::size_t lda, std::size_t rows, std::size_t d, const double* m,
                         std::size_t ldm, double* q) {
#if defined(INSMC_QUADRATIC_FORMS_AVX2)
  if (quadratic_forms_avx2_available()) {
    kernels::row_quadratic_forms_avx2(a, lda, rows, d, m, ldm, q);
    return;
  }
#endif
  row_quadratic_forms_generic(a, lda, rows, d, m, ldm, q);
}

Eigen::VectorXd row_quadratic_forms(const Eigen::MatrixXd& a, const Eigen::MatrixXd& m) {
  INSMC_ASSERT(m.rows() == a.cols() && m.cols() == a.cols(), "a {} × {} matrix for rows of {} columns", m.rows(),
               m.cols(), a.cols());
  Eigen::VectorXd q(a.rows());
  if (a.rows() == 0) return q;
  if (a.cols() == 0) return q.setZero();
  row_quadratic_forms(a.data(), static_cast<std::size_t>(a.outerStride()), static_cast<std::size_t>(a.rows()),
                      static_cast<std::size_t>(a.cols()), m.data(), static_cast<std::size_t>(m.outerStride()),
                      q.data());
  return q;
}

void weighted_gram_generic(const double* a, std::size_t lda, std::size_t rows, std::size_t d, const double* w,
                           double* g, std::size_t ldg) {
  weighted_gram_loop(a, lda, rows, d, w, g, ldg);
}

Eigen::MatrixXd weighted_gram(const Eigen::Ref<const Eigen::MatrixXd>& a, const Eigen::VectorXd& w) {
  INSMC_ASSERT(w.size() == a.rows(), "{} weights for {} rows", w.size(), a.rows());
  Eigen::MatrixXd g = Eigen::MatrixXd::Zero(a.cols(), a.cols());
  if (a.rows() == 0 || a.cols() == 0) return g;
  const auto lda = static_cast<std::size_t>(a.outerStride()), rows = static_cast<std::size_t>(a.rows()),
             d = static_cast<std::size_t>(a.cols()), ldg = static_cast<std::size_t>(g.outerStride());
#if defined(INSMC_QUADRATIC_FORMS_AVX2)
  if (quadratic_forms_avx2_available())
    kernels::weighted_gram_avx2(a.data(), lda, rows, d, w.data(), g.data(), ldg);
  else
#endif
    weighted_gram_generic(a.data(), lda, rows, d, w.data(), g.data(), ldg);
  g.triangularView<Eigen::StrictlyUpper>() = g.transpose();
  return g;
}

}  // namespace insmc::runs
