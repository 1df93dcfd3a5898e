// The linear level: numerical accuracy of the ODE integration, agreement
// with the report's closed form where the report's model is used, and the
// measured, attributed difference where the report is corrected.
#include "lib/propagation/linear_model.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "lib/propagation/closed_form.h"
#include "lib/propagation/k_matrices.h"
#include "lib/propagation/paper_model.h"
#include "tests/unit/lib/propagation/test_support.h"

namespace insmc {
namespace {

TEST(SchulerOde, ConstantForcingMatchesTheExactSolution) {
  const ModelOptions o;
  const double ws = o.schuler_radps();
  auto forcing = [](double) {
    Sensitivity3 u = Sensitivity3::Zero();
    u(1, 0) = 1e-3;
    return u;
  };
  Sensitivity3 r0 = Sensitivity3::Zero(), v0 = Sensitivity3::Zero();
  r0(0, 1) = 100.0;
  v0(2, 2) = 0.3;
  const std::vector<double> times = {0.0, 1.0, 2520.0, 5040.0, 7200.0};
  const auto maps = integrate_schuler_ode(forcing, r0, v0, times, ws, 2.0);
  for (size_t n = 0; n < times.size(); ++n) {
    const double t = times[n];
    EXPECT_NEAR(maps[n](1, 0), 1e-3 / (ws * ws) * (1 - std::cos(ws * t)), 1e-6);
    EXPECT_NEAR(maps[n](0, 1), 100.0 * std::cos(ws * t), 1e-6);
    EXPECT_NEAR(maps[n](2, 2), 0.3 * std::sin(ws * t) / ws, 1e-6);
  }
}

TEST(SchulerOde, HalvingTheStepChangesTheResultByFarLessThanAMetre) {
  const ModelOptions o;
  for (System s : {System::kTheodolite, System::kGyrocompass}) {
    const LinearErrorModel model(s, o);
    const std::vector<double> times = {2520.0, 5040.0, 7200.0};
    const auto coarse = linear_position_maps(model, times, 4.0);
    const auto fine = linear_position_maps(model, times, 2.0);
    for (size_t n = 0; n < times.size(); ++n) {
      for (int i = 0; i < uncertainty_slot::kDim; ++i) {
        // 1 mm at the bound: RK4's error (ω_s h)⁴ is ~1e-11 relative.
        EXPECT_LT((coarse[n].col(i) - fine[n].col(i)).norm() * default_bounds()[i], 1e-3)
            << testing::name_of(i);
      }
    }
  }
}

TEST(LinearModel, ReportsOwnModelIntegratedEqualsCorrected327) {
  // With every form as printed, the ODE solution must equal (3.27) (K6
  // corrected, errata.md#3-27) up to the (ω_ie/ω_s)⁴ truncation of (3.27).
  const ModelOptions o;
  const auto times = testing::minutes_1_to_90();
  for (System s : {System::kTheodolite, System::kGyrocompass}) {
    const LinearErrorModel model(s, o, LinearModelForm::as_printed());
    const KMatrices k = paper_k_matrices(s, o);
    const auto ode = linear_position_maps(model, times);
    for (size_t n = 0; n < times.size(); ++n) {
      const auto f = closed_form_3_27(times[n], o, Form327::kCorrected);
      Sensitivity3 cf = f.initial_position * model.initial_position() +
                        f.initial_velocity_s * model.initial_velocity();
      for (int j = 0; j < 11; ++j) cf += o.radius_m * f.k[j] * k[j];
      for (int i = 0; i < uncertainty_slot::kDim; ++i) {
        EXPECT_LT(testing::difference_at_bound_ft(ode[n], cf, i), 25.0)
            << "system " << system_number(s) << " " << testing::name_of(i);
      }
    }
  }
}

TEST(LinearModel, DifferenceFromThePaperLevelIsAttributedTermByTerm) {
  // Corrected linear model vs the report's short-run form (3.29) at the
  // Table 3.1 bounds, 1–90 min. Every uncertainty stays within the report's
  // 1,300 ft cut except these, each for a stated reason (errata.md):
  //  * g·MUY_x,y,z: (3.13) lacks cos L0 (the correction is 29 % of the term);
  //  * δf_y, system 2: the K4 bias terms (3.29d) drops exceed the cut;
  //  * ζ_rx, system 2: (2.18a) C' = C + ζ_r read literally, whereas (2.17d)
  //    passes ζ_rx through the gyrocompass as −ζ_rx tan L0 on C'_z.
  const ModelOptions o;
  const auto times = testing::minutes_1_to_90();
  for (System s : {System::kTheodolite, System::kGyrocompass}) {
    const LinearErrorModel model(s, o);
    const ShortRunMatrices m = paper_short_run_matrices(s, o);
    const auto ode = linear_position_maps(model, times);
    std::map<int, double> worst;
    for (size_t n = 0; n < times.size(); ++n) {
      const Sensitivity3 paper = short_run_position_map(m, times[n], o);
      for (int i = 0; i < uncertainty_slot::kDim; ++i)
        worst[i] = std::max(worst[i], testing::difference_at_bound_ft(ode[n], paper, i));
    }
    for (int i = 0; i < uncertainty_slot::kDim; ++i) {
      const bool muy = i >= uncertainty_slot::kGyroMuyDrift && i < uncertainty_slot::kGyroMuyDrift + 3;
      const bool sys2 = s == System::kGyrocompass;
      const bool named = muy || (sys2 && (i == uncertainty_slot::kAccelBias + 1 || i == uncertainty_slot::kMisalignAlign + 0));
      if (named) {
        EXPECT_GT(worst[i], 1300.0) << testing::name_of(i) << " was expected to exceed the cut";
      } else {
        EXPECT_LT(worst[i], 1300.0) << "system " << system_number(s) << " " << testing::name_of(i);
      }
    }
  }
}

TEST(LinearModel, EveryUncertaintyZeroGivesNoError) {
  const ModelOptions o;
  const LinearErrorModel model(System::kGyrocompass, o);
  const auto maps = linear_position_maps(model, {5400.0});
  EXPECT_EQ((maps[0] * UncertaintyVector::Zero()).norm(), 0.0);
}

TEST(LinearModel, GyroDriftZAloneReproducesTheReportsFigures) {
  // §5.2: the U4·ω_ie T term of (5.9b) "will give a 1.56 n.m. maximum error
  // for t' = 84 minutes when T = 20 minutes and ω_doz = 10 meru":
  // r0 (ω_ie/ω_s) (2 ω_doz cos L0/ω_ie) ω_ie T (ω_s t' − sin ω_s t').
  const ModelOptions o;
  const ShortRunMatrices m = paper_short_run_matrices(System::kTheodolite, o);
  const double w_doz = 10 * kMeruToRadps, T = 1200.0, tp = 84 * 60.0;
  const auto f = short_run_functions_3_29(tp, o);
  const double err_m = o.radius_m * f.u3 * m.u4(0, uncertainty_slot::kGyroDrift + 2) * w_doz * o.earth_rate_radps * T;
  EXPECT_NEAR(err_m / kNmiToM, 1.56, 0.02);
}

}  // namespace
}  // namespace insmc
