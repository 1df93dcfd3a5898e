#pragma once
/// Each row's quadratic form a_i M a_iᵀ and the weighted Gram Aᵀ W A, the
/// cost of a run model's fit: a
/// row's normalizer q_i = h S Π S hᵀ and its spread under the actual noise
/// are two of them per row and layout (run_analysis.h). Taken row by row
/// from M's lower triangle, they cost half the product A M that Eigen would
/// form, and the rows are independent, so wider vector units take several
/// at once (an AVX2 kernel picked at run time; the same sums in the same
/// order, so the same bits on any x86-64).
#include <Eigen/Core>
#include <cstddef>

namespace insmc::runs {

/// q[i] = Σ_k Σ_j A(i,k) M(k,j) A(i,j) for the `rows` rows of A (column-major,
/// leading dimension lda, d columns) and M symmetric d × d (column-major,
/// leading dimension ldm; only its lower triangle and diagonal are read).
void row_quadratic_forms(const double* a, std::size_t lda, std::size_t rows, std::size_t d, const double* m,
                         std::size_t ldm, double* q);

/// The same for Eigen matrices: A is rows × d, M is d × d.
Eigen::VectorXd row_quadratic_forms(const Eigen::MatrixXd& a, const Eigen::MatrixXd& m);

/// Aᵀ diag(w) A (d × d), the information a fit's rows carry: each entry's
/// sum over the rows in fixed lanes, the lower triangle computed and mirrored.
Eigen::MatrixXd weighted_gram(const Eigen::Ref<const Eigen::MatrixXd>& a, const Eigen::VectorXd& w);

/// Whether the AVX2 kernels run on this CPU (and were built).
bool quadratic_forms_avx2_available();
/// The generic kernels, whatever the CPU (for tests against the AVX2 ones).
void weighted_gram_generic(const double* a, std::size_t lda, std::size_t rows, std::size_t d, const double* w,
                           double* g, std::size_t ldg);
void row_quadratic_forms_generic(const double* a, std::size_t lda, std::size_t rows, std::size_t d, const double* m,
                                 std::size_t ldm, double* q);

}  // namespace insmc::runs
