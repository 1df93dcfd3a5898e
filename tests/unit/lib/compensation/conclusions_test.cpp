// The report's conclusions about the test run and its text figures for
// scheme 5.2, checked against the model (the scheme ranking by covariance
// and the Monte Carlo of the text-figure study are in
// tests/regression/compensation_conclusions_test.cpp, which needs the
// Monte Carlo library):
//  * §4.3, §6: "the test run should last at least 10 minutes, preferably 15
//    minutes, in order to determine the fixed gyro drift rates when 0.1
//    ft/sec velocity increments ... are assumed";
//  * §4.3, §6: U4 (the acceleration-sensitive drifts) cannot be estimated
//    from a test run under 15–20 minutes;
//  * §5.2: with T = 20 min and ω_doz = 10 meru, the U4 ½ω_ie²T² term gives
//    "a maximum of 2,300 feet error for ... t' = 42 minutes" and the U4 ω_ie T
//    term "a 1.56 n.m. maximum error for t' = 84 minutes".
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <string>

#include "lib/common/input_error.h"
#include "lib/preflight/test_run.h"
#include "lib/uncertainty/uncertainty_model.h"
#include "tests/unit/lib/compensation/residual_fit.h"

namespace insmc {
namespace {

constexpr double kPulseMps = 0.1 * kFtpsToMps;  // §4.3: ΔV = 0.1 ft/s
constexpr double kOneMeru = kMeruToRadps;

/// The (4.6) U3 limit as a drift rate: U3y = −ω_dox/ω_ie (3.29c), so a U3
/// coefficient u is a drift ω_ie u. `pulses` = 3 is (4.6); §4.3 also reads
/// the table with "a minimum of 10 pulses".
double drift_resolution_radps(double test_s, double pulses, const ModelOptions& m) {
  return m.earth_rate_radps * pulse_resolution_limits(kPulseMps, test_s, m).u3 * pulses / 3.0;
}

/// RMS of the estimate errors the ΔV pulses alone cause, with the
/// covariance's additive model (one uniform remainder U_k on [0, ΔV) per
/// count, Δf_k = (… + U_{k−1} − U_k)/τ): row `row` of the accelerometer
/// estimator (0: Â1, 1: Û3, 2: Û4).
double accel_estimate_noise_rms(const TestRunEstimators& est, const TestRunOptions& o, int row) {
  const int K = o.intervals();
  double sum = 0;
  for (int j = 0; j <= K; ++j) {  // remainder U_j enters Δf_j with −1/τ and Δf_{j+1} with +1/τ
    const double next = j < K ? est.accel(row, j) : 0.0, here = j > 0 ? est.accel(row, j - 1) : 0.0;
    sum += std::pow((next - here) / o.filter_interval_s, 2);
  }
  return o.dv_pulse_mps * std::sqrt(sum / 12);
}

/// Same for the position estimator (rows 1: Û2, 2: Û3, 3: Û4): dithered
/// rounding e_k on [−q/2, q/2] per reading, differenced with e_0.
double position_estimate_noise_rms(const TestRunEstimators& est, const TestRunOptions& o, int row) {
  const double sum_sq = est.position.row(row).squaredNorm(), sum = est.position.row(row).sum();
  return o.position_resolution_m * std::sqrt((sum_sq + sum * sum) / 12);
}

// ------------------------------------------------------------ gyro drift from a short test run

// Decision: "determine the fixed gyro drift rates" is read as resolving a
// drift of 1 meru, the report's own yardstick in §4.3 ("a resolution for
// T = 10 minutes better than 1 meru"; one tenth of Table 3.1's 10 meru).
// The (4.6) three-pulse limit in drift units, 6ΔV/(g T²), reaches 1 meru
// at T* = sqrt(6ΔV/(g · 1 meru)) = 8.4 min; with §4.3's "minimum of 10
// pulses" at sqrt(10/3) T* = 15.4 min. So a test run under 8.4 min cannot
// resolve 1 meru under either reading, 10 min resolves it with three pulses
// only, and 15 min gives ≈ 1 meru (1.07) with ten: the report's "at least 10
// minutes, preferably 15". The code's resolvable_terms() asks another
// question — is U3 worth fitting against its prior RMS (several meru-
// equivalents with Table 3.1) — and says yes already at 5 min.
TEST(CompensationConclusions, ShortTestRunsCannotResolveGyroDrift) {
  const ModelOptions m;
  const double crossing_3 = std::sqrt(6 * kPulseMps / (m.gravity_mps2 * kOneMeru));
  const double crossing_10 = std::sqrt(10.0 / 3.0) * crossing_3;
  std::cout << fmt::format("1-meru drift resolution reached at T = {:.2f} min (3 pulses), {:.2f} min (10 pulses)\n",
                           crossing_3 / 60, crossing_10 / 60);
  EXPECT_GT(crossing_3, 5 * 60.0);
  EXPECT_LT(crossing_3, 10 * 60.0);
  EXPECT_GT(crossing_10, 15 * 60.0);
  // "preferably 15 minutes": ten pulses give 1 meru to within the report's rounding.
  EXPECT_NEAR(drift_resolution_radps(15 * 60.0, 10, m) / kOneMeru, 1.0, 0.1);

  TestRunOptions test;
  test.dv_pulse_mps = kPulseMps;
  const UncertaintyModel table_3_1;
  for (double minutes : {5.0, 10.0, 15.0, 20.0}) {
    test.duration_s = minutes * 60.0;
    const double r3 = drift_resolution_radps(test.duration_s, 3, m) / kOneMeru;
    const double r10 = drift_resolution_radps(test.duration_s, 10, m) / kOneMeru;
    const TestRunEstimators est = make_estimators(test, m, true, false);
    const double pulse_rms = m.earth_rate_radps * accel_estimate_noise_rms(est, test, 1) / kOneMeru;
    const Resolvability r = resolvable_terms(System::kTheodolite, m, test, table_3_1);
    std::cout << fmt::format(
        "T = {:2.0f} min: (4.6) drift resolution {:.2f} meru (3 pulses), {:.2f} meru (10 pulses); RMS drift error from "
        "the pulses alone (additive model, accelerometer fit U1..U3) {:.3f} meru; resolvable_terms: u3 {} (limit "
        "{:.2e} vs prior RMS {:.2e})\n",
        minutes, r3, r10, pulse_rms, r.u3, r.u3_limit, r.u3_prior_rms);
    if (minutes < crossing_3 / 60) {
      EXPECT_GT(r3, 1.0) << minutes << " min";
    } else {
      EXPECT_LT(r3, 1.0) << minutes << " min";
    }
    // The worst case of (4.6) bounds the RMS of uniform rounding errors.
    EXPECT_LT(pulse_rms, r3) << minutes << " min";
    EXPECT_TRUE(r.u3) << minutes << " min: U3's prior RMS exceeds its (4.6) limit from 5 min on";
  }
}

// The code's (4.6) criterion says U4 is not resolvable at 15 min and is at
// 20 min with the Table 3.1 defaults (uniform, largest-axis prior RMS of U4
// about 10e-3 against limits 14.5e-3 and 6.1e-3). The report's "not likely
// ... for test times less than 15 minutes or even 20 minutes because in
// addition to the bad resolution, we can also have estimation errors" is the
// stricter statement: at 20 min the estimate's own error from the pulses is
// printed below against U4's prior RMS: with 0.1 ft/s pulses the RMS error
// of Û4 from the accelerometer fit is above U4's prior RMS at 15 min and
// still above half of it at 20 min (the position fit at 3 ft does better:
// 55% and 17%) — an estimate that cannot be relied on, as the report says,
// although (4.6) calls it resolvable at 20 min.
constexpr double kUnreliableFraction = 0.5;

TEST(CompensationConclusions, U4IsNotResolvableAt15MinAndIsAt20Min) {
  const ModelOptions m;
  const UncertaintyModel table_3_1;
  for (System sys : {System::kTheodolite, System::kGyrocompass}) {
    for (double minutes : {15.0, 20.0}) {
      TestRunOptions test;
      test.duration_s = minutes * 60.0;
      const Resolvability r = resolvable_terms(sys, m, test, table_3_1);
      const TestRunEstimators est = make_estimators(test, m, true, true);
      std::cout << fmt::format(
          "system {}, T = {:.0f} min: U4 limit {:.2e}, prior RMS {:.2e}, resolvable {}; RMS of Û4's error from the "
          "pulses alone {:.2e} (accelerometer fit), from the 3 ft resolution {:.2e} (position fit)\n",
          system_number(sys), minutes, r.u4_limit, r.u4_prior_rms, r.u4, accel_estimate_noise_rms(est, test, 2),
          position_estimate_noise_rms(est, test, 3));
      EXPECT_EQ(r.u4, minutes >= 20.0) << "system " << system_number(sys) << ", T = " << minutes << " min";
      const double accel_error = accel_estimate_noise_rms(est, test, 2);
      EXPECT_GT(accel_error, (minutes >= 20.0 ? kUnreliableFraction : 1.0) * r.u4_prior_rms) << minutes << " min";
    }
  }
  // Asking for U4 where it is not resolvable is an input error (exit 2 in the CLI).
  TestRunOptions short_test;
  short_test.duration_s = 5 * 60.0;
  short_test.fit_u4 = FitU4::kYes;
  const Resolvability r = resolvable_terms(System::kTheodolite, m, short_test, table_3_1);
  EXPECT_FALSE(r.u4);
  EXPECT_THROW(make_estimators(short_test, m, r.u3, r.u4), InputError);
}

// ------------------------------------------------------------ the 5.2 text figures

// `--dist all=zero --dist gyro_drift_z=fixed:10meru`, scheme 5.2, T = 20 min,
// x axis (U4x = 2ω_doz cos L0/ω_ie, (3.29d)). The terms alone, from the
// maps: the (1 − cos ω_s t') coefficient of the derived residual (ideal
// estimates: E2 = E3 = 0) is U4 ½ω_ie²T², its (ω_s t' − sin ω_s t')
// coefficient U4 ω_ie T (5.9a, b).
constexpr double kFigureTestS = 20 * 60.0;
constexpr double kFigure42Ft = 2300;   // "a maximum of 2,300 feet", two digits
constexpr double kFigure84Nmi = 1.56;  // "a 1.56 n.m. maximum error", three digits
// 2,300 is printed to two digits: ± half a unit of the second digit.
constexpr double kTwoDigitsFt = 50;
// The derived U4 ω_ie T term is 1.572 n.m. at t' = 84 min; the report's 1.56
// is r0 ω_ie U4 ω_ie T t', i.e. ω_s t' − sin ω_s t' taken as ω_s t' (1.564):
// an allowance of 1% covers that reading.
constexpr double kFigure84Allowance = 0.01;

TEST(CompensationConclusions, TextFiguresOfScheme52AreTheU4TermsAlone) {
  const ModelOptions m;
  TestRunOptions test;
  test.duration_s = kFigureTestS;
  const double w = m.earth_rate_radps, ws = m.schuler_radps(), r0 = m.radius_m, x = 10 * kOneMeru;
  const int j = uncertainty_slot::kGyroDrift + 2;
  for (System sys : {System::kTheodolite, System::kGyrocompass}) {
    const testing::FitResult fit = testing::scheme_coefficients(Scheme::k5_2, sys, m, test, SchemeForms::kPrinted);
    const double c2 = fit.c[testing::kU2](0, j), c3 = fit.c[testing::kU3](0, j);
    const double u4x = 2 * std::cos(m.latitude_rad) / w;  // per unit ω_doz
    EXPECT_NEAR(c2, u4x * 0.5 * std::pow(w * kFigureTestS, 2), 1e-9 * std::abs(c2));
    EXPECT_NEAR(c3, u4x * w * kFigureTestS, 1e-9 * std::abs(c3));
    const double at42_ft = c2 * x * testing::time_function(testing::kU2, 42 * 60.0, m) / kFtToM;
    const double at84_nmi = c3 * x * testing::time_function(testing::kU3, 84 * 60.0, m) / kNmiToM;
    const double at84_no_sin = c3 * x * r0 * (w / ws) * (ws * 84 * 60.0) / kNmiToM;
    std::cout << fmt::format(
        "system {}: U4 ½ω²T² term at t' = 42 min {:.0f} ft (report 2,300); U4 ω T term at "
        "t' = 84 min {:.3f} n.m. ({:.3f} without the sin term; report 1.56)\n",
        system_number(sys), at42_ft, at84_nmi, at84_no_sin);
    EXPECT_NEAR(at42_ft, kFigure42Ft, kTwoDigitsFt);
    EXPECT_NEAR(at84_nmi, kFigure84Nmi, kFigure84Allowance * kFigure84Nmi);
  }
}

// What the whole 5.2 residual of that study is, not just the quoted terms:
// the maps with the estimates as the least-squares fits (noise-free,
// continuous data at the paper level) produce them, for the fits the study
// may run. The fit sees the U4 (t⁴) signal of ω_doz and aliases part of it
// into Û2 (and Û3 when fitted). The Monte Carlo of the same study (pulses,
// resolution) is in tests/regression/compensation_conclusions_test.cpp.
TEST(CompensationConclusions, WholeScheme52ResidualOfTheTextFigureStudy) {
  const ModelOptions m;
  TestRunOptions test;
  test.duration_s = kFigureTestS;
  const int j = uncertainty_slot::kGyroDrift + 2;
  const double x = 10 * kOneMeru;
  const System sys = System::kTheodolite;
  const TestRunMaps data = test_run_maps(sys, Fidelity::kPaper, m, test);
  const std::vector<double> times = {42 * 60.0, 84 * 60.0};
  const SchemeMaps maps = scheme_position_maps(Scheme::k5_2, sys, Fidelity::kPaper, m, test, times);
  // Ideal estimates (E = 0) for reference.
  const Eigen::MatrixXd ideal = testing::perturbations(sys, m, test);
  struct Variant {
    const char* what;
    bool u3, u4;
  };
  for (const Variant& v : {Variant{"ideal (E2 = E3 = 0)", false, false}, Variant{"fit U1,U2", false, false},
                           Variant{"fit U1,U2,U3", true, false}, Variant{"fit U1..U4", true, true}}) {
    ExtendedVector z = ExtendedVector::Zero();
    z[j] = x;
    if (std::string(v.what).starts_with("ideal")) {
      z = ideal.col(j) * x;
    } else {
      const TestRunEstimators est = make_estimators(test, m, v.u3, v.u4);
      for (int a = 0; a < 3; ++a) {
        Eigen::VectorXd d(test.intervals());
        for (int k = 1; k <= test.intervals(); ++k) d[k - 1] = data.position_change[static_cast<size_t>(k)](a, j) * x;
        const Eigen::Vector4d u = est.position * d;
        z[z_slot::kU2 + a] = u[1];
        z[z_slot::kU3 + a] = u[2];
      }
    }
    const double at42 = (maps.position[0] * z)[0] / kFtToM, at84 = (maps.position[1] * z)[0] / kFtToM;
    std::cout << fmt::format(
        "5.2, T = 20 min, ω_doz = 10 meru, x axis, {:<20}: Û2x = {:+.3e}, Û3x = {:+.3e}; "
        "δr_x(t' = 42 min) = {:6.0f} ft, δr_x(t' = 84 min) = {:6.0f} ft = {:.2f} n.m.\n",
        v.what, z[z_slot::kU2], z[z_slot::kU3], at42, at84, at84 * kFtToM / kNmiToM);
    // Whatever the fit, the U4 t'² term (not estimable) keeps the error at
    // 84 min far above the quoted U4 ω_ie T term alone.
    EXPECT_GT(std::abs(at84), 1.5 * kFigure84Nmi * kNmiToM / kFtToM) << v.what;
  }
}

}  // namespace
}  // namespace insmc
