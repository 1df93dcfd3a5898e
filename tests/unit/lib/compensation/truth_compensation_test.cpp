// Every compensation scheme at the truth level against the same scheme on the
// linear level, run by run (docs/truth-vs-models.md): |truth − linear| ≤ 1% |linear| + 1 m
// at t = 1..90 min on the scheme's clock. The linear side is built here from
// the linear test-run maps and compensation_maps.h (the extended vector z of
// one sample, continuous outputs so that both levels see the same data
// without a quantization draw). As in simulator_test.cpp the truth is taken
// by its odd part (r(x, ζ) − r(−x, −ζ))/2: the products of uncertainties the
// linear level drops by construction (e.g. ½ C'_z d_y in system 2) are even.
//
// One first-order term the linear level drops: its single g is both the
// gravitation that sets the Schuler frequency (μ/r0²) and the specific force
// the platform senses; the truth has the site's g_s, less by the centrifugal
// term (ε = 1 − g_s/g = 0.17% at 45°). Uncompensated this is a relative
// difference of ε (measured: ≤ 0.18%), within 1%. A scheme removes most of
// the error with estimates that carry the same relative difference ε, so the
// compensated difference is bounded by ε (|removed| + |left|) ≤ 2ε |r_none|,
// r_none the uncompensated linear error of the same run at the same time
// since its switch-over — while 1% of the small compensated error may be
// less (5.1.2, system 1: ω_cp from Û3 is ε off, up to 40 m at the drift
// bounds against a 26 m residual). That term is attributed: the bound is
// 1% |linear| + 1 m + 2ε |r_none|, and the printout says where the
// attribution was needed.
#include "lib/compensation/truth_compensation.h"

#include <gtest/gtest.h>

#include <cstdio>

#include "lib/alignment/alignment.h"
#include "lib/compensation/compensation_maps.h"
#include "lib/propagation/position_maps.h"
#include "lib/uncertainty/catalogue.h"
#include "lib/uncertainty/uncertainty_model.h"
#include "tests/unit/lib/propagation/test_support.h"

namespace insmc {
namespace {

using testing::minutes_1_to_90;
using testing::within_bounds;

/// Truth options with continuous outputs (no ΔV pulses) for system s.
TruthOptions continuous(System s) {
  TruthOptions o;
  o.system = s;
  o.dv_pulse_mps = 0.0;
  return o;
}

struct Case {
  ModelOptions model;
  TestRunOptions test;
  TestRunEstimators estimators;
  TestRunMaps maps;
  Sensitivity3 torquer_map, align_accel_map;
};

Case make_case(System s) {
  Case c;
  c.test.dv_pulse_mps = 0.0;           // continuous outputs on both levels
  c.test.position_resolution_m = 0.0;
  c.test.torquer_pulse_rad = 0.0;      // 5.4: torquer commands read continuously too
  const Resolvability r = resolvable_terms(s, c.model, c.test, UncertaintyModel());
  c.estimators = make_estimators(c.test, c.model, r.u3, r.u4);
  c.maps = test_run_maps(s, Fidelity::kLinear, c.model, c.test);
  const Sensitivity3 steady = full_steady_state_misalignment(s, c.model);
  c.torquer_map = torquer_commands(steady, c.model);
  c.align_accel_map = alignment_accelerometer_outputs(steady, c.model);
  return c;
}

/// The linear level's z for one sample with continuous outputs.
ExtendedVector linear_z(const Case& c, const UncertaintyVector& x, const UncertaintyVector& realigned) {
  const int K = c.test.intervals();
  const double g = c.model.gravity_mps2, w = c.model.earth_rate_radps, T = c.test.duration_s;
  const double tau = c.test.filter_interval_s;
  ExtendedVector z = ExtendedVector::Zero();
  z.head<ux::kDim>() = x;
  for (const RealignedSlot& r : kRealignedSlots) z[r.z_index] = realigned[r.x_index];
  Eigen::MatrixXd pos(K, 3), acc(K, 3);
  for (int k = 1; k <= K; ++k) {
    pos.row(k - 1) = (c.maps.position_change[k] * x).transpose();
    acc.row(k - 1) = ((c.maps.velocity_increment[k] - c.maps.velocity_increment[k - 1]) * x / tau).transpose();
  }
  const Eigen::Matrix<double, 4, 3> up = c.estimators.position * pos;
  const Eigen::Matrix<double, 3, 3> ua = c.estimators.accel * acc;
  for (int a = 0; a < 3; ++a) {
    z[ez::kU2 + a] = up(1, a);
    z[ez::kU3 + a] = up(2, a);
    z[ez::kU3Accel + a] = ua(1, a);
    z[ez::kDfT + a] = g * (ua(0, a) + w * T * ua(1, a) + w * w * T * T / 2 * ua(2, a));
  }
  z.segment<3>(ez::kTorquerCommands) = c.torquer_map * x;
  z.segment<3>(ez::kAlignAccel) = c.align_accel_map * x;
  return z;
}

TEST(TruthCompensation, EverySchemeAgreesWithTheLinearLevelRunByRun) {
  const std::vector<double> times = minutes_1_to_90();
  for (System s : {System::kTheodolite, System::kGyrocompass}) {
    const Case c = make_case(s);
    TruthOptions o = continuous(s);
    o.filter_interval_s = c.test.filter_interval_s;
    const double epsilon =
        1.0 - simulate_truth(o, UncertaintyVector::Zero(), {60.0}).site_gravity_mps2 / c.model.gravity_mps2;
    ASSERT_GT(epsilon, 0.0);
    ASSERT_LT(epsilon, 0.0035);
    const TruthSchemeSetup setup(o, c.test, c.estimators);
    for (Scheme scheme : all_schemes()) {
      const SchemeMaps maps = scheme_position_maps(scheme, s, Fidelity::kLinear, c.model, c.test, times);
      std::vector<double> since_switchover(times);
      for (double& t : since_switchover) t += resets_at_test_end(scheme) ? c.test.duration_s : 0.0;
      const std::vector<Sensitivity3> none = position_maps(s, Fidelity::kLinear, c.model, since_switchover);
      for (std::uint64_t seed : {1u, 2u}) {
        TruthSchemeSample plus, minus;
        plus.x = within_bounds(seed);
        plus.realigned_x = plus.x;
        const UncertaintyVector fresh = within_bounds(seed + 100);
        for (const RealignedSlot& r : kRealignedSlots) plus.realigned_x[r.x_index] = fresh[r.x_index];
        minus.x = -plus.x;
        minus.realigned_x = -plus.realigned_x;
        const TruthSchemeRun a = run_truth_scheme(scheme, setup, plus, times);
        const TruthSchemeRun b = run_truth_scheme(scheme, setup, minus, times);
        const ExtendedVector z = linear_z(c, plus.x, plus.realigned_x);
        const UncertaintyVector& x_run = realigns(scheme) ? plus.realigned_x : plus.x;
        double worst_m = 0.0, worst_raw_excess = -1e300, worst_excess = -1e300;
        for (std::size_t k = 0; k < times.size(); ++k) {
          const Vec3 odd = 0.5 * (a.flight.position_error_ap_m[k] - b.flight.position_error_ap_m[k]);
          const Vec3 lin = maps.position[k] * z;
          const double d = (odd - lin).norm(), raw_bound = 0.01 * lin.norm() + 1.0;
          worst_m = std::max(worst_m, d);
          worst_raw_excess = std::max(worst_raw_excess, d - raw_bound);
          worst_excess = std::max(worst_excess, d - raw_bound - 2.0 * epsilon * (none[k] * x_run).norm());
        }
        EXPECT_LE(worst_excess, 0.0) << "scheme " << to_string(scheme) << " system " << system_number(s)
                                     << " seed " << seed << ": worst |truth − linear| " << worst_m << " m";
        std::printf("  %-8s system %d seed %d: worst |odd truth - linear| %7.3f m, %s\n",
                    std::string(to_string(scheme)).c_str(), system_number(s), static_cast<int>(seed), worst_m,
                    worst_raw_excess <= 0 ? "within 1% + 1 m" : "within 1% + 1 m only with the single-g term");
      }
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
    near(0.5 * (ep.u2 - em.u2), z.segment<3>(ez::kU2), "U2");
    near(0.5 * (ep.u3 - em.u3), z.segment<3>(ez::kU3), "U3");
    near(0.5 * (ep.u3_accel - em.u3_accel), z.segment<3>(ez::kU3Accel), "U3 from f");
    near(0.5 * (ep.df_at_test_end_mps2 - em.df_at_test_end_mps2) / c.model.gravity_mps2,
         z.segment<3>(ez::kDfT) / c.model.gravity_mps2, "df(T)/g");
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
  x.segment<3>(ux::kInitialVelocity) = default_bounds().segment<3>(ux::kInitialVelocity);
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
