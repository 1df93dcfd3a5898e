// The printed K1..K11 of (3.25) against the forcing of (3.24) computed from
// its matrices (B(t), D(t), Ψ, Z, A, α) by the linear model: an independent
// derivation of the same quantity.
#include "lib/propagation/k_matrices.h"

#include <gtest/gtest.h>

#include "lib/propagation/linear_model.h"
#include "tests/unit/lib/propagation/test_support.h"

namespace insmc {
namespace {

Sensitivity3 k_forcing(const KMatrices& k, double t, const ModelOptions& o) {
  const auto f = k_time_functions(o.earth_rate_radps * t);
  Sensitivity3 u = Sensitivity3::Zero();
  for (int j = 0; j < 11; ++j) u += o.gravity_mps2 * f[j] * k[j];
  return u;
}

// Both sides are sums of ~30 products of order g·1e-3: round-off only.
constexpr double kRoundoffMps2 = 1e-15;

TEST(KMatrices, PrintedExpansionEqualsTheForcingOfEquation324) {
  const ModelOptions o;
  for (System s : {System::kTheodolite, System::kGyrocompass}) {
    const LinearErrorModel model(s, o, LinearModelForm::as_printed());
    const KMatrices k = paper_k_matrices(s, o);
    for (double t : testing::minutes_1_to_90()) {
      const Sensitivity3 diff = model.forcing(t) - k_forcing(k, t, o);
      for (int i = 0; i < uncertainty_slot::kDim; ++i) {
        EXPECT_LT(diff.col(i).norm() * default_bounds()[i], kRoundoffMps2)
            << "system " << system_number(s) << " t=" << t << " " << testing::name_of(i);
      }
    }
  }
}

TEST(KMatrices, TheGMuyDriftOfEquation313LacksCosL0) {
  // errata.md#3-13: the specific force along y seen by the space-stabilized
  // platform is g cos L0 sin ω_ie t, so the g·MUY drift angle is
  // g·MUY cos L0 (1 − cos ω_ie t)/ω_ie. Only the g·MUY columns change, and by
  // exactly cos L0.
  const ModelOptions o;
  const LinearErrorModel printed(System::kTheodolite, o, LinearModelForm::as_printed());
  LinearModelForm corrected_form = LinearModelForm::as_printed();
  corrected_form.corrected_muy = true;
  const LinearErrorModel corrected(System::kTheodolite, o, corrected_form);
  const KMatrices k_corr = corrected_k_matrices(System::kTheodolite, o);
  for (double t : testing::minutes_1_to_90()) {
    const Sensitivity3 a = printed.forcing(t), b = corrected.forcing(t);
    for (int i = 0; i < uncertainty_slot::kDim; ++i) {
      const bool is_muy = i >= uncertainty_slot::kGyroMuyDrift && i < uncertainty_slot::kGyroMuyDrift + 3;
      const double scale = is_muy ? std::cos(o.latitude_rad) : 1.0;
      const double bound = default_bounds()[i];
      EXPECT_LT((b.col(i) - scale * a.col(i)).norm() * bound, kRoundoffMps2) << testing::name_of(i);
      EXPECT_LT((b.col(i) - k_forcing(k_corr, t, o).col(i)).norm() * bound, kRoundoffMps2)
          << testing::name_of(i);
    }
  }
}

TEST(KMatrices, TimeFunctionsAtZeroAndSmallAngles) {
  const auto f0 = k_time_functions(0.0);
  EXPECT_EQ(f0[0], 1.0);
  for (int j = 1; j < 11; ++j) EXPECT_EQ(f0[j], 0.0) << j;
  const double p = 1e-4;  // leading powers: φ, φ, φ²/2, φ², φ³/2, φ³/6, φ³/2, φ⁴/4, φ⁴/6, φ⁵/12
  const auto f = k_time_functions(p);
  const double expected[] = {1, p, p, p * p / 2, p * p, p * p * p / 2, p * p * p / 6, p * p * p / 2,
                             p * p * p * p / 4, p * p * p * p / 6, p * p * p * p * p / 12};
  for (int j = 0; j < 11; ++j) EXPECT_NEAR(f[j] / expected[j], 1.0, 1e-3) << "K" << j + 1;
}

}  // namespace
}  // namespace insmc
