// Every compensation scheme at the truth level against the same scheme on the
// linear level, run by run (the case and its bound: scheme_case.h), and the
// truth-level pieces the schemes rely on.
#include "lib/compensation/truth_compensation.h"

#include <gtest/gtest.h>

#include <cstdio>

#include "lib/alignment/alignment.h"
#include "lib/compensation/compensation_maps.h"
#include "lib/propagation/position_maps.h"
#include "lib/uncertainty/catalogue.h"
#include "lib/uncertainty/uncertainty_model.h"
#include "tests/unit/lib/compensation/scheme_case.h"
#include "tests/unit/lib/propagation/test_support.h"

namespace insmc {
namespace {

using testing::Agreement;
using testing::Case;
using testing::continuous;
using testing::make_case;
using testing::truth_linear_agreement;
using testing::within_bounds;

void print(const Agreement& a, Scheme scheme, System s, std::uint64_t seed) {
  std::printf("  %-8s system %d seed %d: worst |odd truth - linear| %7.3f m, %s\n", std::string(to_string(scheme)).c_str(),
              system_number(s), static_cast<int>(seed), a.worst_m,
              a.worst_raw_excess_m <= 0 ? "within 1% + 1 m" : "within 1% + 1 m only with the single-g term");
}

TEST(TruthCompensation, EverySchemeAgreesWithTheLinearLevelRunByRun) {
  for (System s : {System::kTheodolite, System::kGyrocompass}) {
    const Case c = make_case(s);
    for (Scheme scheme : all_schemes())
      for (std::uint64_t seed : {1u, 2u}) {
        const Agreement a = truth_linear_agreement(c, scheme, seed);
        EXPECT_LE(a.worst_excess_m, 0.0) << "scheme " << to_string(scheme) << " system " << system_number(s)
                                         << " seed " << seed << ": worst |truth − linear| " << a.worst_m << " m";
        print(a, scheme, s, seed);
      }
  }
}

TEST(TruthCompensation, TestRunEstimatesAgreeWithTheLinearLevel) {
  // The estimates the schemes use, from truth data, against the linear data's.
  for (System s : {System::kTheodolite, System::kGyrocompass}) {
    const Case c = make_case(s);
    TruthOptions o = continuous(s);
    const UncertaintyVector x = within_bounds(7);
    const TruthRun plus = simulate_truth(o, x, uniform_times(c.test.duration_s, c.test.filter_interval_s));
    const TruthRun minus = simulate_truth(o, -x, uniform_times(c.test.duration_s, c.test.filter_interval_s));
    const TestRunEstimates ep = estimate_test_run(plus, c.test, c.estimators, c.model);
    const TestRunEstimates em = estimate_test_run(minus, c.test, c.estimators, c.model);
    const ExtendedVector z = linear_z(c, x, x);
    // Û is dimensionless (a tilt or drift angle per g): 1% of it, or 1e-7
    // (0.1 µrad, a tenth of a metre of position at r0/…​).
    const auto near = [](const Vec3& truth, const Vec3& linear, const char* what) {
      EXPECT_LE((truth - linear).norm(), 0.01 * linear.norm() + 1e-7) << what << " " << truth.transpose() << " vs "
                                                                       << linear.transpose();
    };
    near(0.5 * (ep.u2 - em.u2), z.segment<3>(z_slot::kU2), "U2");
    near(0.5 * (ep.u3 - em.u3), z.segment<3>(z_slot::kU3), "U3");
    near(0.5 * (ep.u3_accel - em.u3_accel), z.segment<3>(z_slot::kU3Accel), "U3 from f");
    near(0.5 * (ep.df_at_test_end_mps2 - em.df_at_test_end_mps2) / c.model.gravity_mps2,
         z.segment<3>(z_slot::kDfT) / c.model.gravity_mps2, "df(T)/g");
  }
}

TEST(TruthCompensation, EachSchemeUsesItsOwnEstimates) {
  // A test run whose position data are zero and whose accelerometer data
  // carry a slope: 5.3 (accelerometer data, (5.10)–(5.12)) must react to it,
  // 5.2 (position data, (5.8)) must not — both against all-zero data.
  const Case c = make_case(System::kTheodolite);
  TruthOptions o = continuous(System::kTheodolite);
  const TruthSchemeSetup setup(o, c.test, c.estimators);
  TruthSchemeSample sample;
  sample.x = within_bounds(3);
  sample.realigned_x = sample.x;
  TruthRun zero = simulate_truth(o, UncertaintyVector::Zero(), uniform_times(c.test.duration_s, c.test.filter_interval_s));
  for (auto& r : zero.position_error_ap_m) r.setZero();
  for (auto& f : zero.accel_error_ap_mps2) f.setZero();
  TruthRun sloped = zero;
  for (std::size_t k = 0; k < sloped.t_s.size(); ++k) sloped.accel_error_ap_mps2[k].x() = 1e-7 * sloped.t_s[k];
  const TestRunEstimates e = estimate_test_run(sloped, c.test, c.estimators, c.model);
  EXPECT_EQ(e.u2, Vec3::Zero());
  EXPECT_EQ(e.u3, Vec3::Zero());
  EXPECT_NE(e.u3_accel.x(), 0.0);
  const std::vector<double> times{2520.0, 5040.0};
  const auto flight = [&](Scheme scheme, const TruthRun& test) {
    return run_truth_scheme(scheme, setup, sample, times, {}, &test).flight.position_error_ap_m[1];
  };
  EXPECT_EQ(flight(Scheme::k5_2, sloped), flight(Scheme::k5_2, zero));
  EXPECT_GT((flight(Scheme::k5_3, sloped) - flight(Scheme::k5_3, zero)).norm(), 1.0);
}

TEST(TruthCompensation, Scheme54WithSettledAlignmentLoopsEqualsTheSteadyState) {
  // 5.4 measures what the alignment saw: with the loops simulated for 3 h
  // their averaged commands are the steady state's, and so is the flight.
  for (System s : {System::kTheodolite, System::kGyrocompass}) {
    const Case c = make_case(s);
    TruthOptions o = continuous(s);
    TruthOptions loops = o;
    loops.alignment_loops = AlignmentLoopSettings{};
    loops.alignment_loops->duration_s = 3 * 3600.0;
    TruthSchemeSample sample;
    sample.x = within_bounds(4);
    sample.realigned_x = sample.x;
    const std::vector<double> times{2520.0, 3780.0, 5040.0};
    const TruthSchemeRun a = run_truth_scheme(Scheme::k5_4, TruthSchemeSetup(o, c.test, c.estimators), sample, times);
    const TruthSchemeRun b = run_truth_scheme(Scheme::k5_4, TruthSchemeSetup(loops, c.test, c.estimators), sample, times);
    for (std::size_t k = 0; k < times.size(); ++k)
      EXPECT_LT((a.flight.position_error_ap_m[k] - b.flight.position_error_ap_m[k]).norm(), 0.1) << times[k];
  }
}

TEST(TruthCompensation, ResetSetsTheComputerToItsStationaryValues) {
  // With every uncertainty zero except the initial velocity wiggle (u)V, the
  // uncompensated run oscillates at the Schuler period; a reset at T sets the
  // computer's velocity without the wiggle, so the error after T is the
  // (zero) error of a stationary computer: below a millimetre.
  TruthOptions o = continuous(System::kTheodolite);
  UncertaintyVector x = UncertaintyVector::Zero();
  x.segment<3>(uncertainty_slot::kInitialVelocity) = default_bounds().segment<3>(uncertainty_slot::kInitialVelocity);
  const std::vector<double> times{600.0, 900.0, 1200.0, 3600.0};
  const TruthRun free = simulate_truth(o, x, times);
  o.reset_at_s = 900.0;
  const TruthRun reset = simulate_truth(o, x, times);
  EXPECT_GT(free.position_error_ap_m[3].norm(), 1.0);
  EXPECT_EQ(reset.position_error_ap_m[0], free.position_error_ap_m[0]);  // before the reset: untouched
  for (std::size_t k = 1; k < times.size(); ++k) EXPECT_LT(reset.position_error_ap_m[k].norm(), 1e-3) << times[k];
}

TEST(TruthCompensation, PointTwoStepIsABiasTheAlignmentNeverSaw) {
  // A compensation step c at point 2 from t = 0 acts on the computer like an
  // accelerometer bias after switch-over: x error (1 − cos ω_s t) c_x / ω_s².
  TruthOptions o = continuous(System::kTheodolite);
  o.accel_compensation.step_mps2 = Vec3(1e-4, 0.0, 0.0);
  const double ws = o.model.schuler_radps(), t = 1800.0;
  const TruthRun run = simulate_truth(o, UncertaintyVector::Zero(), {t});
  const double expected = (1.0 - std::cos(ws * t)) * 1e-4 / (ws * ws);
  EXPECT_NEAR(run.position_error_ap_m[0].x(), expected, 0.01 * std::abs(expected) + 0.1);
  // The instruments, and so the recorded Δf^a, do not see it.
  TruthOptions plain = o;
  plain.accel_compensation = AccelCompensation{};
  EXPECT_EQ(run.accel_error_ap_mps2[0], simulate_truth(plain, UncertaintyVector::Zero(), {t}).accel_error_ap_mps2[0]);
}

}  // namespace
}  // namespace insmc
