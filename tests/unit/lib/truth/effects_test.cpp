// Each named effect's signature in the truth simulator's outputs: what the
// gap diagnosis should find when the effect is on. Continuous accelerometer
// output and x = 0 where the signature is to be seen alone.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "lib/frames/frames.h"
#include "lib/truth/earth_model.h"
#include "lib/truth/effect.h"
#include "lib/truth/simulator.h"
#include "lib/uncertainty/catalogue.h"

namespace insmc {
namespace {

TruthOptions options_with(const std::string& effect, double dv_pulse_mps = 0.0) {
  TruthOptions o;
  o.dv_pulse_mps = dv_pulse_mps;
  if (!effect.empty()) o.effects = {parse_effect(effect)};
  return o;
}

/// The context the simulator realizes effects with (for tests that need the
/// realized values; only noise and the grid matter for the effects used).
Perturbations realized(const std::string& effect, const NormalSource& noise, double duration_s) {
  EffectContext c;
  c.duration_s = duration_s;
  c.noise = &noise;
  const std::vector<EffectSpec> specs = {parse_effect(effect)};
  return realize_effects(specs, c);
}

/// Overlapping Allan variance of samples y_k (averages over τ0) at cluster m.
double allan_variance(const std::vector<double>& y, int m) {
  const int n = static_cast<int>(y.size());
  std::vector<double> prefix(n + 1, 0.0);
  for (int k = 0; k < n; ++k) prefix[k + 1] = prefix[k] + y[k];
  double sum = 0.0;
  int terms = 0;
  for (int j = 0; j + 2 * m <= n; ++j) {
    const double a = (prefix[j + m] - prefix[j]) / m, b = (prefix[j + 2 * m] - prefix[j + m]) / m;
    sum += (b - a) * (b - a);
    ++terms;
  }
  return sum / (2.0 * terms);
}

/// Allan deviation of Δf on `axis` at clusters m1 and m2 (τ = 10 s m), pooled
/// over `runs` runs of 6000 s with the given effect, x = 0.
std::pair<double, double> allan_of_accel_error(const std::string& effect, int axis, int m1, int m2,
                                               int runs) {
  const std::vector<double> times = uniform_times(6000.0, 10.0);
  double v1 = 0.0, v2 = 0.0;
  for (int r = 0; r < runs; ++r) {
    const NormalSource noise = hashed_normal_source(500 + r);
    const TruthRun run = simulate_truth(options_with(effect), UncertaintyVector::Zero(), times, noise);
    std::vector<double> y;
    for (std::size_t k = 1; k < times.size(); ++k) y.push_back(run.accel_error_ap_mps2[k][axis]);
    v1 += allan_variance(y, m1);
    v2 += allan_variance(y, m2);
  }
  return {std::sqrt(v1 / runs), std::sqrt(v2 / runs)};
}

double slope(const std::pair<double, double>& a, int m1, int m2) {
  return std::log(a.second / a.first) / std::log(static_cast<double>(m2) / m1);
}

TEST(Effects, VelocityRandomWalkIsWhiteAccelerometerNoise) {
  // White specific-force noise: Allan deviation N/sqrt(τ), slope −½,
  // N = velocity_1h / sqrt(3600 s) = 0.005 m/s/√s.
  const auto a = allan_of_accel_error("velocity_random_walk", 0, 1, 20, 6);
  EXPECT_NEAR(slope(a, 1, 20), -0.5, 0.08);
  EXPECT_NEAR(a.first, 0.005 / std::sqrt(10.0), 0.1 * 0.005 / std::sqrt(10.0));
}

TEST(Effects, AccelBiasRandomWalkHasAllanSlopePlusHalf) {
  // Random-walk bias (tau = 0): rate random walk, σ_A(τ) = K sqrt(τ/3),
  // K = sigma / sqrt(3600 s).
  const auto a = allan_of_accel_error("accel_bias_instability:tau=0s,sigma=0.1mg", 2, 3, 60, 6);
  EXPECT_NEAR(slope(a, 3, 60), 0.5, 0.12);
  const double k = 0.1 * kMgToMps2 / 60.0;
  EXPECT_NEAR(a.second, k * std::sqrt(600.0 / 3.0), 0.3 * k * std::sqrt(600.0 / 3.0));
}

TEST(Effects, AngleRandomWalkTiltsThePlatformByARandomWalk) {
  // The platform angle θ wanders; the x accelerometer sees g θ_y: Δf_x is a
  // random walk with K = g angle_1h / sqrt(3600 s), slope +½.
  const auto a = allan_of_accel_error("angle_random_walk", 0, 3, 60, 6);
  EXPECT_NEAR(slope(a, 3, 60), 0.5, 0.12);
  const double k = kGravityMps2 * 0.1 * kMradToRad / 60.0;
  EXPECT_NEAR(a.second, k * std::sqrt(600.0 / 3.0), 0.3 * k * std::sqrt(600.0 / 3.0));
}

TEST(Effects, AccelBiasGaussMarkovIsNulledAtSwitchOverThenWanders) {
  // The alignment sees the bias b(0) present at switch-over like a constant
  // δf: against the run with δf = b(0) the accelerometer output error differs
  // by exactly b(t) − b(0) (averaged over the filter interval) on every axis.
  const std::vector<double> times = uniform_times(3000.0, 10.0);
  const NormalSource noise = hashed_normal_source(21);
  const std::string effect = "accel_bias_instability:sigma=0.1mg,tau=200s";
  const TruthRun run = simulate_truth(options_with(effect), UncertaintyVector::Zero(), times, noise);
  const Perturbations p = realized(effect, noise, times.back());
  UncertaintyVector x = UncertaintyVector::Zero();
  x.segment<3>(uncertainty_slot::kAccelBias) = p.bias_process.at(0.0);
  const TruthRun constant = simulate_truth(options_with(""), x, times);
  double change = 0.0;
  for (std::size_t k = 1; k < times.size(); ++k) {
    const Vec3 expected = p.bias_process.integrals(times[k] - 10.0, times[k]).first / 10.0 - p.bias_process.at(0.0);
    const Vec3 d = run.accel_error_ap_mps2[k] - constant.accel_error_ap_mps2[k];
    EXPECT_LT((d - expected).norm(), 1e-12) << times[k];
    change = std::max(change, expected.norm());
  }
  EXPECT_GT(change, 0.1 * kMgToMps2);  // it does wander
}

TEST(Effects, GyroDriftInstabilityTurnsThePlatform) {
  // x = 0: the platform turns by C' (the alignment's response to the drift at
  // switch-over) plus d(t) = ∫_0^t ω(s) ds of the realized drift process, so
  // to first order Δf = −(C' + d(t)) × f^{a'}(t), f^{a'} = C_n^{a'}(t)(0, 0, −g_s)
  // (3.16) — averaged over the filter interval.
  const std::vector<double> times = uniform_times(3000.0, 10.0);
  const NormalSource noise = hashed_normal_source(22);
  const std::string effect = "gyro_drift_instability:sigma=5meru,tau=600s";
  const TruthOptions o = options_with(effect);
  const TruthRun run = simulate_truth(o, UncertaintyVector::Zero(), times, noise);
  const Perturbations p = realized(effect, noise, times.back());
  const ModelOptions& m = o.model;
  double largest = 0.0;
  Vec3 d_start = Vec3::Zero();  // d(t − 10), accumulated interval by interval
  for (std::size_t k = 1; k < times.size(); ++k) {
    const double t = times[k];
    // Mean of d over (t − 10, t], exactly: ∫_{t−10}^{t} d = ∫_{t−10}^{t}(t − s)ω(s) ds + 10 d(t − 10).
    const GridProcess::Integrals step = p.drift_process.integrals(t - 10.0, t);
    const Vec3 mean_d = (step.second + 10.0 * d_start) / 10.0;
    d_start += step.first;
    const Vec3 f_ap = C_ap_n(m.latitude_rad, m.earth_rate_radps * (t - 5.0)) * Vec3(0, 0, -run.site_gravity_mps2);
    const Vec3 expected = -(run.switchover_misalignment_rad + mean_d).cross(f_ap);
    // Second order: |C' + d|² g ~ 1e-11 g; f^{a'} turns by 4e-4 rad over
    // the interval (its mean taken at the midpoint).
    EXPECT_LT((run.accel_error_ap_mps2[k] - expected).norm(), 1e-3 * expected.norm() + 1e-8) << t;
    largest = std::max(largest, expected.norm());
  }
  EXPECT_GT(largest, 10.0 * kUgToMps2);
}

TEST(Effects, ThermalTransientSettlesExponentially) {
  // Against the same run with a constant bias equal to the transient's value
  // at switch-over (what the alignment saw): the difference is the settling
  // B (e^{−t/τ} − 1) on every axis, B = bias e^{−warmup/τ}.
  const std::vector<double> times = uniform_times(3600.0, 10.0);
  const std::string effect = "thermal_transient:bias=0.2mg,drift=0meru,tau=900s,warmup=600s";
  const TruthRun with = simulate_truth(options_with(effect), UncertaintyVector::Zero(), times);
  const double b = 0.2 * kMgToMps2 * std::exp(-600.0 / 900.0);
  UncertaintyVector x = UncertaintyVector::Zero();
  x.segment<3>(uncertainty_slot::kAccelBias) = Vec3::Constant(b);
  const TruthRun constant = simulate_truth(options_with(""), x, times);
  for (std::size_t k = 1; k < times.size(); ++k) {
    const double t = times[k];
    // Mean of e^{−s/τ} − 1 over (t − 10, t].
    const double settling = 900.0 / 10.0 * (std::exp(-(t - 10.0) / 900.0) - std::exp(-t / 900.0)) - 1.0;
    const Vec3 d = with.accel_error_ap_mps2[k] - constant.accel_error_ap_mps2[k];
    for (int a = 0; a < 3; ++a) EXPECT_NEAR(d[a], b * settling, 1e-3 * b) << "axis " << a << " t " << t;
  }
  // The drift part moves the position too.
  const TruthRun drift = simulate_truth(options_with("thermal_transient:bias=0mg"), UncertaintyVector::Zero(), times);
  EXPECT_GT(drift.position_error_ap_m.back().norm(), 100.0);
}

TEST(Effects, AnisoelasticDriftActsLikeMassUnbalanceOnTheTurningGravity) {
  // ω_x = c f_y f_z ≈ −c g_s f_y and ω_y = c f_z f_x ≈ −c g_s f_x: to first
  // order the catalogue's g·MUY_x = −c g_s² and ω_MU,y = −c g_s² sin L0 cos L0
  // (3.13a, through MUX_y); the rest is third order in the earth's turn.
  const auto times = uniform_times(5400.0, 300.0);
  const double coefficient = 5.0 * kMeruToRadps;
  const TruthRun with = simulate_truth(options_with("anisoelastic_drift:coefficient=5meru"),
                                       UncertaintyVector::Zero(), times);
  const double c_gs2 = coefficient * std::pow(with.site_gravity_mps2 / kGravityMps2, 2);
  const double L = TruthOptions{}.model.latitude_rad;
  UncertaintyVector x = UncertaintyVector::Zero();
  x[uncertainty_slot::kGyroMuyDrift + 0] = -c_gs2;
  x[uncertainty_slot::kGyroMuDrift + 1] = -c_gs2 * std::sin(L) * std::cos(L);
  const TruthRun equivalent = simulate_truth(options_with(""), x, times);
  for (std::size_t k = 1; k < times.size(); ++k) {
    const Vec3 a = with.position_error_ap_m[k], b = equivalent.position_error_ap_m[k];
    EXPECT_LT((a - b).norm(), 0.02 * b.norm() + 1.0) << times[k] << ": " << a.transpose() << " vs "
                                                    << b.transpose();
  }
  EXPECT_GT(with.position_error_ap_m.back().norm(), 1000.0);
}

TEST(Effects, ScaleFactorNonlinearityAddsTheSquareOfTheForce) {
  // x = 0: the platform is a'; Δf = k2/g² ⊙ f^{a'}(t)² averaged over the
  // interval, f^{a'} = C_n^{a'}(t) (0, 0, −g_s).
  const std::vector<double> times = uniform_times(5400.0, 60.0);
  const TruthOptions o = options_with("scale_factor_nonlinearity:k2=0.5mg");
  const TruthRun run = simulate_truth(o, UncertaintyVector::Zero(), times);
  const double q = 0.5 * kMgToMps2 / (kGravityMps2 * kGravityMps2);
  const ModelOptions& m = o.model;
  for (std::size_t k = 1; k < times.size(); ++k) {
    Vec3 mean = Vec3::Zero();
    for (int j = 0; j <= 2; ++j) {
      const double s = times[k] - 10.0 + 5.0 * j;
      const Vec3 f = C_ap_n(m.latitude_rad, m.earth_rate_radps * s) * Vec3(0, 0, -run.site_gravity_mps2);
      mean += (j == 1 ? 4.0 : 1.0) / 6.0 * q * f.cwiseAbs2();
    }
    EXPECT_LT((run.accel_error_ap_mps2[k] - mean).norm(), 1e-9) << times[k];
  }
}

TEST(Effects, GravityModelErrorHasTheSizeOfJ2) {
  // The truth's plumb line at L0 has J2 in it, the computer's map from L̂0 to
  // a position does not: the computer starts (3/2) J2 sin 2L0 r0 ≈ 10.3 km
  // north of the vehicle (exactly: the difference of the two maps).
  const std::vector<double> times = {0.0, 2520.0, 5040.0};
  const TruthOptions o = options_with("gravity_model");
  const TruthRun run = simulate_truth(o, UncertaintyVector::Zero(), times);
  const ModelOptions& m = o.model;
  const double L = m.latitude_rad, w = m.earth_rate_radps, r0 = m.radius_m;
  const Vec3 sphere = position_for_plumb_latitude(model_gravity_field(m.gravity_mps2, r0, 0.0), w, r0, L);
  const Vec3 oblate = position_for_plumb_latitude(model_gravity_field(m.gravity_mps2, r0, kEarthJ2), w, r0, L);
  const Vec3 expected0 = C_ap_i(L) * (sphere - oblate);
  EXPECT_LT((run.position_error_ap_m[0] - expected0).norm(), 1e-6);
  EXPECT_NEAR(run.position_error_ap_m[0].x(), 1.5 * kEarthJ2 * std::sin(2 * L) * r0,
              0.02 * 1.5 * kEarthJ2 * r0);
  // Both the initial offset and the computed gravitation are off by ~1.6e-3
  // (of r0 and g): the error stays of the order of 10 km.
  for (const Vec3& e : run.position_error_ap_m) {
    EXPECT_GT(e.norm(), 3e3);
    EXPECT_LT(e.norm(), 3e4);
  }
}

TEST(Effects, DeflectionOfVerticalAddsToTheCataloguesXiEta) {
  const std::vector<double> times = uniform_times(5400.0, 600.0);
  const TruthRun with = simulate_truth(options_with("deflection_of_vertical:xi=0.2mrad,eta=-0.1mrad"),
                                       UncertaintyVector::Zero(), times);
  UncertaintyVector x = UncertaintyVector::Zero();
  x[uncertainty_slot::kDeflection + 0] = 0.2e-3;
  x[uncertainty_slot::kDeflection + 1] = -0.1e-3;
  const TruthRun same = simulate_truth(options_with(""), x, times);
  for (std::size_t k = 0; k < times.size(); ++k)
    EXPECT_LT((with.position_error_ap_m[k] - same.position_error_ap_m[k]).norm(), 1e-9);
  EXPECT_GT(with.position_error_ap_m.back().norm(), 50.0);
}

TEST(Effects, SwitchTransientIsAStepInMisalignmentAndBias) {
  // Exactly ζ_r and ∂f (and δf_z) larger by the realized steps.
  const std::vector<double> times = uniform_times(5400.0, 300.0);
  const NormalSource noise = hashed_normal_source(31);
  const Perturbations p = realized("switch_transient", noise, times.back());
  const TruthRun with = simulate_truth(options_with("switch_transient"), UncertaintyVector::Zero(), times, noise);
  UncertaintyVector x = UncertaintyVector::Zero();
  x.segment<3>(uncertainty_slot::kMisalignAlign) = p.misalignment_step_rad;
  x.segment<2>(uncertainty_slot::kBiasChangeAlign) = p.nav_bias_step_mps2.head<2>();
  x[uncertainty_slot::kAccelBias + 2] = p.nav_bias_step_mps2.z();
  const TruthRun same = simulate_truth(options_with(""), x, times);
  for (std::size_t k = 0; k < times.size(); ++k)
    EXPECT_LT((with.position_error_ap_m[k] - same.position_error_ap_m[k]).norm(), 1e-6);
  EXPECT_GT(p.misalignment_step_rad.norm(), 1e-5);
}

TEST(Effects, AlignmentTransientLeavesTheDecayedCoarseError) {
  // Residual misalignment per axis ~ N(0, (initial e^{−duration/τ})²):
  // 5 mrad e^{−5} = 34 µrad level, 20 mrad e^{−3} = 1.0 mrad azimuth.
  const int n = 2000;
  Vec3 sum2 = Vec3::Zero();
  for (int r = 0; r < n; ++r) {
    const NormalSource noise = hashed_normal_source(1000 + r);
    sum2 += realized("alignment_transient", noise, 10.0).misalignment_step_rad.cwiseAbs2();
  }
  const Vec3 rms = (sum2 / n).cwiseSqrt();
  const double level = 5e-3 * std::exp(-5.0), azimuth = 20e-3 * std::exp(-3.0);
  EXPECT_NEAR(rms.x(), level, 0.05 * level);
  EXPECT_NEAR(rms.y(), level, 0.05 * level);
  EXPECT_NEAR(rms.z(), azimuth, 0.05 * azimuth);
  // In the simulator: C' moves by the realized step.
  const NormalSource noise = hashed_normal_source(1);
  const Perturbations p = realized("alignment_transient", noise, 10.0);
  const TruthRun with = simulate_truth(options_with("alignment_transient"), UncertaintyVector::Zero(), {0.0}, noise);
  EXPECT_LT((with.switchover_misalignment_rad - p.misalignment_step_rad).norm(), 1e-15);
}

TEST(Effects, SwayShowsAsFilteredAccelerationAndAnInitialVelocityError) {
  // x = 0: Δf over each interval is the sway velocity change over it, turned
  // into a' (the platform); the computer starts at the nominal point at rest,
  // so δr(0) = −s(0) and the velocity wiggle −ṡ(0) starts a Schuler oscillation.
  const std::vector<double> times = uniform_times(1200.0, 10.0);
  const NormalSource noise = hashed_normal_source(41);
  const TruthOptions o = options_with("sway");
  const TruthRun run = simulate_truth(o, UncertaintyVector::Zero(), times, noise);
  const Perturbations p = realized("sway", noise, times.back());
  const ModelOptions& m = o.model;
  const auto sway = [&](double t, bool velocity) {
    Vec3 v = Vec3::Zero();
    for (const SwayComponent& c : p.sway) {
      const double w = 2.0 * std::numbers::pi / c.period_s;
      v += (velocity ? w * std::cos(w * t + c.phase_rad) : std::sin(w * t + c.phase_rad)) * c.amplitude_n_m;
    }
    return v;
  };
  // Inertial velocity of the sway in a': C_n^{a'}(t) (ṡ + Ω^n × s),
  // Ω^n = ω_ie (cos L0, 0, −sin L0).
  const Vec3 omega_n = m.earth_rate_radps * Vec3(std::cos(m.latitude_rad), 0.0, -std::sin(m.latitude_rad));
  const auto inertial_velocity = [&](double t) {
    return Vec3(C_ap_n(m.latitude_rad, m.earth_rate_radps * t) * (sway(t, true) + omega_n.cross(sway(t, false))));
  };
  double rms = 0.0;
  for (std::size_t k = 1; k < times.size(); ++k) {
    const double t = times[k];
    const Vec3 expected = (inertial_velocity(t) - inertial_velocity(t - 10.0)) / 10.0;
    EXPECT_LT((run.accel_error_ap_mps2[k] - expected).norm(), 1e-9) << t;
    rms += run.accel_error_ap_mps2[k].squaredNorm();
  }
  EXPECT_GT(std::sqrt(rms / (times.size() - 1)), 0.5 * kMgToMps2);  // clearly above 0.1 ft/s / 10 s
  EXPECT_LT((run.position_error_ap_m[0] + sway(0.0, false)).norm(), 1e-9);
  // δr(t) ≈ −s(0) cos ω_s t − ṡ(0) sin(ω_s t)/ω_s + s(0) − s(t) … the
  // oscillation dominates: compare at t where the sway terms are centimetres.
  const double ws = m.schuler_radps();
  const Vec3 s0 = sway(0.0, false), v0 = sway(0.0, true);
  for (std::size_t k = 60; k < times.size(); k += 30) {
    const double t = times[k];
    const Vec3 expected = -(s0 * std::cos(ws * t) + v0 * std::sin(ws * t) / ws);
    EXPECT_LT((run.position_error_ap_m[k].head<2>() - expected.head<2>()).norm(), 0.5) << t;
  }
}

TEST(Effects, CoarserQuantizationReplacesThePulseWeight) {
  const std::vector<double> times = uniform_times(3000.0, 10.0);
  const UncertaintyVector x = 0.5 * default_bounds();
  const TruthRun fine = simulate_truth(options_with("", 0.1 * kFtpsToMps), x, times);
  const TruthRun coarse = simulate_truth(options_with("quantization:dv_pulse=1ftps", 0.1 * kFtpsToMps), x, times);
  EXPECT_DOUBLE_EQ(coarse.dv_pulse_mps, kFtpsToMps);
  double fine_noise = 0.0, coarse_noise = 0.0;
  for (std::size_t k = 1; k < times.size(); ++k) {
    // w n / τ − Δf is the expected specific force f̂, the same for both.
    const Vec3 f_hat_fine = fine.dv_pulse_mps * fine.pulse_counts[k].cast<double>() / 10.0 - fine.accel_error_ap_mps2[k];
    const Vec3 f_hat_coarse =
        coarse.dv_pulse_mps * coarse.pulse_counts[k].cast<double>() / 10.0 - coarse.accel_error_ap_mps2[k];
    EXPECT_LT((f_hat_fine - f_hat_coarse).norm(), 1e-9);
    if (k > 1) {
      fine_noise += (fine.accel_error_ap_mps2[k] - fine.accel_error_ap_mps2[k - 1]).squaredNorm();
      coarse_noise += (coarse.accel_error_ap_mps2[k] - coarse.accel_error_ap_mps2[k - 1]).squaredNorm();
    }
  }
  // Counting noise grows with the weight (~10× here).
  EXPECT_GT(coarse_noise, 20.0 * fine_noise);
}

}  // namespace
}  // namespace insmc
