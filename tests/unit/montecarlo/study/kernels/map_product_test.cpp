// map_product: every kernel this CPU has gives, bit for bit, the sum of
// map_product.h's definition (k ascending, product then sum), and that is
// Eigen's xᵀ·M, which the engine used before.
#include "montecarlo/study/kernels/map_product.h"

#include "lib/compensation/extended_vector.h"
#include "lib/uncertainty/uncertainty_vector.h"

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

namespace insmc::mc {
namespace {

constexpr ProductKernel kKernels[] = {ProductKernel::Generic, ProductKernel::Avx2, ProductKernel::Avx512};

/// Values over 16 decades of both signs, so that a different order of the
/// sum would round differently.
double spread_value(std::mt19937_64& g) {
  std::uniform_real_distribution<double> mantissa(-1.0, 1.0);
  std::uniform_int_distribution<int> decade(-8, 8);
  const double m = mantissa(g);  // drawn first in every compiler (operand order is unspecified)
  return m * std::pow(10.0, decade(g));
}

/// The definition, element by element.
std::vector<double> reference(ProductShape shape, const std::vector<double>& x, std::size_t ldx,
                              const std::vector<double>& m, std::size_t ldm, std::size_t ldy) {
  std::vector<double> y(ldy * static_cast<std::size_t>(shape.columns), -1.0);
  for (int c = 0; c < shape.columns; ++c)
    for (std::size_t s = 0; s < shape.samples; ++s) {
      double acc = 0.0;
      for (int k = 0; k < shape.depth; ++k)
        acc = acc + x[static_cast<std::size_t>(k) * ldx + s] * m[static_cast<std::size_t>(c) * ldm + static_cast<std::size_t>(k)];
      y[static_cast<std::size_t>(c) * ldy + s] = acc;
    }
  return y;
}

bool same_bits(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}

TEST(MapProduct, EveryKernelGivesTheDefinitionsBitsForEveryShape) {
  std::mt19937_64 g(20261129);
  int kernels_run = 0;
  for (ProductKernel kernel : kKernels) {
    if (!product_kernel_available(kernel)) continue;
    ++kernels_run;
    for (std::size_t n : {0, 1, 3, 4, 7, 8, 15, 16, 17, 33, 1024})
      for (int depth : {0, 1, 2, 33, uncertainty_slot::kDim, z_slot::kDim})
        for (int columns : {1, 2, 3, 4, 5, 6, 7, 11, 13, 15, 30, 105}) {
          const std::size_t ldx = n + 3, ldm = static_cast<std::size_t>(depth) + 1, ldy = n + 5;
          std::vector<double> x(ldx * static_cast<std::size_t>(depth)), m(ldm * static_cast<std::size_t>(columns));
          for (double& v : x) v = spread_value(g);
          for (double& v : m) v = spread_value(g);
          const ProductShape shape{n, depth, columns};
          std::vector<double> y(ldy * static_cast<std::size_t>(columns), -1.0);
          map_product_with(kernel, shape, x.data(), ldx, m.data(), ldm, y.data(), ldy);
          ASSERT_TRUE(same_bits(y, reference(shape, x, ldx, m, ldm, ldy)))
              << product_kernel_name(kernel) << ": n " << n << ", depth " << depth << ", columns " << columns;
        }
  }
  EXPECT_GE(kernels_run, 1);
  EXPECT_TRUE(product_kernel_available(best_product_kernel()));
}

TEST(MapProduct, InfinitiesAndSignedZerosFollowTheDefinition) {
  for (ProductKernel kernel : kKernels) {
    if (!product_kernel_available(kernel)) continue;
    const double inf = std::numeric_limits<double>::infinity();
    const std::size_t n = 19;
    const int depth = 3, columns = 7;
    std::vector<double> x(n * depth), m(static_cast<std::size_t>(depth * columns));
    for (std::size_t i = 0; i < x.size(); ++i) x[i] = i % 5 == 0 ? -0.0 : i % 7 == 0 ? inf : 1.0 + static_cast<double>(i);
    for (std::size_t i = 0; i < m.size(); ++i) m[i] = i % 4 == 0 ? -0.0 : -2.0 + static_cast<double>(i);
    std::vector<double> y(n * columns);
    map_product_with(kernel, {n, depth, columns}, x.data(), n, m.data(), depth, y.data(), n);
    const std::vector<double> want = reference({n, depth, columns}, x, n, m, depth, n);
    for (std::size_t i = 0; i < y.size(); ++i) {
      if (std::isnan(want[i])) {
        EXPECT_TRUE(std::isnan(y[i])) << i;
        continue;
      }
      EXPECT_EQ(std::signbit(y[i]), std::signbit(want[i])) << i;
      EXPECT_EQ(y[i], want[i]) << i;
    }
  }
}

// The engine's blocks before this kernel: Eigen's y = xᵀ·M on the same
// shapes (the uncertainties → 15 rows of a system at three times, the
// extended vector → 105 rows of seven schemes) gave these bits for a whole
// block, so the studies' outputs did not change when the kernel replaced it.
TEST(MapProduct, TheEnginesShapesGiveEigensProductBitForBit) {
  std::mt19937_64 g(7);
  for (const auto& [depth, columns] : {std::pair{uncertainty_slot::kDim, 15}, std::pair{uncertainty_slot::kDim, 30}, std::pair{z_slot::kDim, 105},
                                       std::pair{z_slot::kDim, 210}}) {
    const Eigen::Index n = 1024;
    Eigen::MatrixXd x(depth, n), m(depth, columns);  // x sample-major, as Eigen's product took it
    for (Eigen::Index i = 0; i < x.size(); ++i) x.data()[i] = spread_value(g);
    for (Eigen::Index i = 0; i < m.size(); ++i) m.data()[i] = spread_value(g);
    Eigen::MatrixXd eigen(n, columns);
    eigen.noalias() = x.transpose() * m;
    const Eigen::MatrixXd xt = x.transpose();  // draw-major, as the kernel takes it
    Eigen::MatrixXd y(n, columns);
    map_product({static_cast<std::size_t>(n), depth, columns}, xt.data(), static_cast<std::size_t>(n), m.data(),
                static_cast<std::size_t>(depth), y.data(), static_cast<std::size_t>(n));
    EXPECT_EQ(std::memcmp(y.data(), eigen.data(), static_cast<std::size_t>(y.size()) * sizeof(double)), 0)
        << "depth " << depth << ", columns " << columns;
  }
}

}  // namespace
}  // namespace insmc::mc
