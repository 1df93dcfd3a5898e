#pragma once
// A compensation scheme at the truth level against the same scheme on the
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
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <vector>

#include "lib/alignment/alignment.h"
#include "lib/compensation/compensation_maps.h"
#include "lib/compensation/truth_compensation.h"
#include "lib/propagation/position_maps.h"
#include "lib/uncertainty/uncertainty_model.h"
#include "tests/unit/lib/propagation/test_support.h"

namespace insmc::testing {

/// Truth options with continuous outputs (no ΔV pulses) for system s.
inline TruthOptions continuous(System s) {
  TruthOptions o;
  o.system = s;
  o.dv_pulse_mps = 0.0;
  return o;
}

struct Case {
  System system;
  ModelOptions model;
  TestRunOptions test;
  TestRunEstimators estimators;
  TestRunMaps maps;
  Sensitivity3 torquer_map, align_accel_map;
};

inline Case make_case(System s) {
  Case c;
  c.system = s;
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
inline ExtendedVector linear_z(const Case& c, const UncertaintyVector& x, const UncertaintyVector& realigned) {
  const int K = c.test.intervals();
  const double g = c.model.gravity_mps2, w = c.model.earth_rate_radps, T = c.test.duration_s;
  const double tau = c.test.filter_interval_s;
  ExtendedVector z = ExtendedVector::Zero();
  z.head<uncertainty_slot::kDim>() = x;
  for (const RealignedSlot& r : kRealignedSlots) z[r.z_index] = realigned[r.x_index];
  Eigen::MatrixXd pos(K, 3), acc(K, 3);
  for (int k = 1; k <= K; ++k) {
    pos.row(k - 1) = (c.maps.position_change[k] * x).transpose();
    acc.row(k - 1) = ((c.maps.velocity_increment[k] - c.maps.velocity_increment[k - 1]) * x / tau).transpose();
  }
  const Eigen::Matrix<double, 4, 3> up = c.estimators.position * pos;
  const Eigen::Matrix<double, 3, 3> ua = c.estimators.accel * acc;
  for (int a = 0; a < 3; ++a) {
    z[z_slot::kU2 + a] = up(1, a);
    z[z_slot::kU3 + a] = up(2, a);
    z[z_slot::kU3Accel + a] = ua(1, a);
    z[z_slot::kDfT + a] = g * (ua(0, a) + w * T * ua(1, a) + w * w * T * T / 2 * ua(2, a));
  }
  z.segment<3>(z_slot::kTorquerCommands) = c.torquer_map * x;
  z.segment<3>(z_slot::kAlignAccel) = c.align_accel_map * x;
  return z;
}

/// The worst difference over t = 1..90 min between the truth's odd part and
/// the linear level for one scheme and one sample drawn within the bounds
/// (`seed`; the realignment's fresh draws from seed + 100), and its excess
/// over the bound 1% |linear| + 1 m, without (raw) and with the single-g
/// term 2ε |r_none|.
struct Agreement {
  double worst_m = 0.0, worst_raw_excess_m = -1e300, worst_excess_m = -1e300;
};

inline Agreement truth_linear_agreement(const Case& c, Scheme scheme, std::uint64_t seed) {
  const std::vector<double> times = minutes_1_to_90();
  TruthOptions o = continuous(c.system);
  o.filter_interval_s = c.test.filter_interval_s;
  const double epsilon =
      1.0 - simulate_truth(o, UncertaintyVector::Zero(), {60.0}).site_gravity_mps2 / c.model.gravity_mps2;
  EXPECT_GT(epsilon, 0.0);
  EXPECT_LT(epsilon, 0.0035);
  const TruthSchemeSetup setup(o, c.test, c.estimators);
  const SchemeMaps maps = scheme_position_maps(scheme, c.system, Fidelity::kLinear, c.model, c.test, times);
  std::vector<double> since_switchover(times);
  for (double& t : since_switchover) t += resets_at_test_end(scheme) ? c.test.duration_s : 0.0;
  const std::vector<Sensitivity3> none = position_maps(c.system, Fidelity::kLinear, c.model, since_switchover);
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
  Agreement out;
  for (std::size_t k = 0; k < times.size(); ++k) {
    const Vec3 odd = 0.5 * (a.flight.position_error_ap_m[k] - b.flight.position_error_ap_m[k]);
    const Vec3 lin = maps.position[k] * z;
    const double d = (odd - lin).norm(), raw_bound = 0.01 * lin.norm() + 1.0;
    out.worst_m = std::max(out.worst_m, d);
    out.worst_raw_excess_m = std::max(out.worst_raw_excess_m, d - raw_bound);
    out.worst_excess_m = std::max(out.worst_excess_m, d - raw_bound - 2.0 * epsilon * (none[k] * x_run).norm());
  }
  return out;
}

}  // namespace insmc::testing
