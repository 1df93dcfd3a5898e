// The run model's row kernels against Eigen's products, and the AVX2 kernel
// against the generic one bit for bit (the same sums in the same order).
#include "montecarlo/records/runs/model/quadratic_forms.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace insmc::runs {
namespace {

Eigen::MatrixXd random_matrix(Eigen::Index rows, Eigen::Index cols, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> n01;
  Eigen::MatrixXd m(rows, cols);
  for (Eigen::Index j = 0; j < cols; ++j)
    for (Eigen::Index i = 0; i < rows; ++i) m(i, j) = n01(rng);
  return m;
}

TEST(RowQuadraticForms, AreEachRowsFormThroughTheMatrix) {
  // Row counts on and off the kernel's block of 32 rows, and 43 causes (the
  // run model's), 1 and 0.
  for (const auto& [rows, d] : {std::pair{1, 1}, std::pair{31, 43}, std::pair{32, 43}, std::pair{1765, 43},
                                std::pair{100, 7}, std::pair{5, 0}, std::pair{63, 43}, std::pair{20, 43}}) {
    SCOPED_TRACE(::testing::Message() << rows << " rows, " << d << " columns");
    const Eigen::MatrixXd a = random_matrix(rows, d, 3);
    const Eigen::MatrixXd b = random_matrix(d, d, 4);
    const Eigen::MatrixXd m = b * b.transpose();
    const Eigen::VectorXd q = row_quadratic_forms(a, m);
    ASSERT_EQ(q.size(), rows);
    for (Eigen::Index i = 0; i < rows; ++i) {
      // The sum written out (Eigen's products take no matrix of 0 columns).
      double expected = 0.0, scale = 0.0;
      for (Eigen::Index k = 0; k < d; ++k)
        for (Eigen::Index j = 0; j < d; ++j) {
          expected += a(i, k) * m(k, j) * a(i, j);
          scale += std::abs(a(i, k) * m(k, j) * a(i, j));
        }
      EXPECT_NEAR(q[i], expected, 1e-13 * (1.0 + scale));
    }
  }
}

TEST(WeightedGram, IsTheInformationTheRowsCarry) {
  for (const auto& [rows, d] : {std::pair{1, 1}, std::pair{7, 43}, std::pair{8, 43}, std::pair{1003, 43},
                                std::pair{0, 3}}) {
    SCOPED_TRACE(::testing::Message() << rows << " rows, " << d << " columns");
    const Eigen::MatrixXd a = random_matrix(rows, d, 5);
    const Eigen::VectorXd w = random_matrix(rows, 1, 6).col(0).cwiseAbs();
    const Eigen::MatrixXd g = weighted_gram(a, w);
    ASSERT_EQ(g.rows(), d);
    EXPECT_EQ(g, g.transpose());
    for (Eigen::Index k = 0; k < d; ++k)
      for (Eigen::Index j = 0; j < d; ++j) {
        double expected = 0.0, scale = 0.0;
        for (Eigen::Index i = 0; i < rows; ++i) {
          expected += w[i] * a(i, k) * a(i, j);
          scale += std::abs(w[i] * a(i, k) * a(i, j));
        }
        EXPECT_NEAR(g(k, j), expected, 1e-13 * (1.0 + scale));
      }
  }
}
TEST(RowQuadraticForms, ARowsFormIsTheSameBitsWhateverBlockItFallsIn) {
  // 63 rows: a block of 32, then the rest in blocks of 16, 8, 4 and 3 rows;
  // each row alone is a block of one. The sums run in one order whatever the
  // block, so a row's form does not depend on the rows around it.
  const Eigen::MatrixXd a = random_matrix(63, 29, 11);
  const Eigen::MatrixXd b = random_matrix(29, 29, 12);
  const Eigen::MatrixXd m = b * b.transpose();
  const Eigen::VectorXd q = row_quadratic_forms(a, m);
  for (Eigen::Index i = 0; i < a.rows(); ++i) {
    SCOPED_TRACE(::testing::Message() << "row " << i);
    const Eigen::MatrixXd row = a.row(i);
    EXPECT_EQ(row_quadratic_forms(row, m)[0], q[i]);
  }
}

TEST(RowQuadraticForms, TheVectorKernelGivesTheGenericKernelsBits) {
  if (!quadratic_forms_avx2_available()) GTEST_SKIP() << "no AVX2 on this CPU";
  // 1023 rows: 31 blocks of 32, then blocks of 16, 8 and 4 and 3 rows.
  const Eigen::MatrixXd a = random_matrix(1023, 43, 7);
  const Eigen::MatrixXd b = random_matrix(43, 43, 8);
  const Eigen::MatrixXd m = b * b.transpose();
  const Eigen::VectorXd fast = row_quadratic_forms(a, m);
  Eigen::VectorXd generic(a.rows());
  row_quadratic_forms_generic(a.data(), 1023, 1023, 43, m.data(), 43, generic.data());
  EXPECT_EQ(fast, generic);
  const Eigen::VectorXd w = a.col(0).cwiseAbs();
  Eigen::MatrixXd gram = Eigen::MatrixXd::Zero(43, 43);
  weighted_gram_generic(a.data(), 1023, 1023, 43, w.data(), gram.data(), 43);
  gram.triangularView<Eigen::StrictlyUpper>() = gram.transpose();
  EXPECT_EQ(weighted_gram(a, w), gram);
}

}  // namespace
}  // namespace insmc::runs
