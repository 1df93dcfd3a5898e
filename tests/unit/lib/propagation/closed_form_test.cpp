// The report's closed forms against each other and against the numerically
// integrated Schuler-loop ODE driven by the same K-matrix forcing.
#include "lib/propagation/closed_form.h"

#include <gtest/gtest.h>

#include <cmath>

#include "lib/propagation/k_matrices.h"
#include "lib/propagation/linear_model.h"
#include "lib/propagation/paper_model.h"
#include "tests/unit/lib/propagation/test_support.h"

namespace insmc {
namespace {

/// Response r0 h_j(t) of δr̈ + ω_s² δr = g f_j(t), zero initial state, by ODE.
std::vector<double> ode_response(int j, const std::vector<double>& times, const ModelOptions& o) {
  auto forcing = [&](double t) {
    Sensitivity3 u = Sensitivity3::Zero();
    u(0, 0) = o.gravity_mps2 * k_time_functions(o.earth_rate_radps * t)[j];
    return u;
  };
  const auto maps = integrate_schuler_ode(forcing, Sensitivity3::Zero(), Sensitivity3::Zero(),
                                          times, o.schuler_radps(), 1.0);
  std::vector<double> out;
  for (const auto& m : maps) out.push_back(m(0, 0));
  return out;
}

// (3.27) drops terms in (ω_ie/ω_s)^n, n ≥ 4: r0 ε² times partial-fraction
// coefficients that reach 4² = 16 for the 2ω_ie harmonics (K8..K10).
double truncation_tolerance_m(const ModelOptions& o) {
  const double e = std::pow(o.earth_rate_radps / o.schuler_radps(), 2);
  return 16.0 * e * e * o.radius_m;
}

TEST(ClosedForm327, AgreesWithTheOdeTermByTermExceptThePrintedK6) {
  const ModelOptions o;
  const auto times = testing::minutes_1_to_90();
  const double tol = truncation_tolerance_m(o);
  for (int j = 0; j < 11; ++j) {
    const auto ode = ode_response(j, times, o);
    double worst_printed = 0, worst_corrected = 0;
    for (size_t n = 0; n < times.size(); ++n) {
      const double printed = o.radius_m * closed_form_3_27(times[n], o, Form327::kPrinted).k[j];
      const double corrected = o.radius_m * closed_form_3_27(times[n], o, Form327::kCorrected).k[j];
      worst_printed = std::max(worst_printed, std::abs(printed - ode[n]));
      worst_corrected = std::max(worst_corrected, std::abs(corrected - ode[n]));
    }
    EXPECT_LT(worst_corrected, tol) << "K" << j + 1 << " (corrected reading)";
    if (j == 5) {
      // errata.md#3-27: the printed K6 coefficients leave a secular error
      // 4 r0 ε ω_ie t (≈ 24 m per unit 1e-3 of K6 at 90 min): far above the truncation.
      EXPECT_GT(worst_printed, 10 * tol) << "K6 as printed was expected to disagree";
    } else {
      EXPECT_LT(worst_printed, tol) << "K" << j + 1 << " as printed";
    }
  }
}

TEST(ClosedForm327, InitialConditionsGiveTheSchulerOscillation) {
  const ModelOptions o;
  const double ws = o.schuler_radps();
  for (double t : {0.0, 600.0, 2520.0, 5040.0}) {
    const auto f = closed_form_3_27(t, o);
    EXPECT_NEAR(f.initial_position, std::cos(ws * t), 1e-15);
    EXPECT_NEAR(f.initial_velocity_s, std::sin(ws * t) / ws, 1e-9);
  }
}

// (3.28) keeps of (3.27) the terms above 130 ft (Schuler frequency) and
// 1,000 ft after two hours (earth rate) at the Table 3.1 maxima (§3.3).
constexpr double kThreshold328Ft = 130.0 + 1000.0;
// (3.29) keeps the terms above 1,300 ft after 1.5 h (§3.4).
constexpr double kThreshold329Ft = 1300.0;

TEST(ClosedForm328, DropsOnlyTermsBelowTheReportsThresholds) {
  const ModelOptions o;
  for (System s : {System::kTheodolite, System::kGyrocompass}) {
    const KMatrices k = paper_k_matrices(s, o);
    const ShortRunMatrices m = paper_short_run_matrices(s, o);
    for (double t : testing::minutes_1_to_90()) {
      const Sensitivity3 a = closed_form_position_map(k, m.initial_position_m, m.initial_velocity_mps, t, o, true);
      const Sensitivity3 b = closed_form_position_map(k, m.initial_position_m, m.initial_velocity_mps, t, o, false);
      for (int i = 0; i < uncertainty_slot::kDim; ++i) {
        EXPECT_LT(testing::difference_at_bound_ft(a, b, i), kThreshold328Ft)
            << "system " << system_number(s) << " t=" << t / 60 << " min " << testing::name_of(i);
      }
    }
  }
}

TEST(ClosedForm329, ShortRunFormWithinTheReportsThresholdExceptDfyOfSystem2) {
  // The printed U4 (3.29d) keeps gyro terms only. For system 2 the bias δf_y
  // enters K4_y twice, δf_y/g cos²L0 and −ψ_fz sin L0 cos L0 = δf_y/g sin²L0,
  // so r0 (δf_y/g)(1 − cos ω_ie t) reaches 1,593 ft at 90 min and 1 mg:
  // above the report's own 1,300 ft cut (tables/notes/errata.md#3-29).
  const ModelOptions o;
  for (System s : {System::kTheodolite, System::kGyrocompass}) {
    const KMatrices k = paper_k_matrices(s, o);
    const ShortRunMatrices m = paper_short_run_matrices(s, o);
    for (int i = 0; i < uncertainty_slot::kDim; ++i) {
      double worst = 0;
      for (double t : testing::minutes_1_to_90()) {
        const Sensitivity3 a = closed_form_position_map(k, m.initial_position_m, m.initial_velocity_mps, t, o, false);
        worst = std::max(worst, testing::difference_at_bound_ft(a, short_run_position_map(m, t, o), i));
      }
      if (s == System::kGyrocompass && i == uncertainty_slot::kAccelBias + 1) {
        // The dropped K4 term alone: r0 (δf_y/g)(1 − cos ω_ie t) at 90 min and
        // the bound; the other δf_y terms (3.29) drops are under 2% of it.
        const double dropped_ft = o.radius_m * default_bounds()[i] / o.gravity_mps2 *
                                  (1 - std::cos(o.earth_rate_radps * 5400.0)) / kFtToM;
        EXPECT_GT(dropped_ft, kThreshold329Ft);
        EXPECT_NEAR(worst, dropped_ft, 0.02 * dropped_ft);
      } else {
        EXPECT_LT(worst, kThreshold329Ft) << "system " << system_number(s) << " " << testing::name_of(i);
      }
    }
  }
}

TEST(ShortRunFunctions, SmallTimeExpansionsOfSection43HoldBelow15Minutes) {
  // §4.3: for t < 15 min, sin ω_s t ≈ ω_s t, 1 − cos ω_s t ≈ ω_s²t²/2,
  // ω_s t − sin ω_s t ≈ ω_s³t³/6 and ½ω_s²t² − (1 − cos ω_s t) ≈ ω_s⁴t⁴/24.
  // The next term of each series bounds the error: relative (ω_s t)²/6,
  // /12, /20, /30 at ω_s t = 1.117 (15 min).
  const ModelOptions o;
  const double ws = o.schuler_radps(), q = o.earth_rate_radps / ws;
  for (double t = 60.0; t <= 900.0; t += 60.0) {
    const double x = ws * t;
    const auto f = short_run_functions_3_29(t, o);
    EXPECT_NEAR(f.initial_velocity_s * ws / x, 1.0, x * x / 6);
    EXPECT_NEAR(f.u2 / (x * x / 2), 1.0, x * x / 12);
    EXPECT_NEAR(f.u3 / (q * x * x * x / 6), 1.0, x * x / 20);
    EXPECT_NEAR(f.u4 / (q * q * x * x * x * x / 24), 1.0, x * x / 30);
  }
}

TEST(ShortRunFunctions, U5TermOf330DiffersFromTheTruncatedOneByTheSchulerPart) {
  const ModelOptions o;
  const double q = o.earth_rate_radps / o.schuler_radps();
  for (double t : {600.0, 2520.0, 5040.0}) {
    const double x = o.schuler_radps() * t;
    EXPECT_NEAR(short_run_functions_3_29(t, o).u5 - u5_function_3_30(t, o), q * q * q * (x - std::sin(x)), 1e-15);
  }
}

}  // namespace
}  // namespace insmc
