// The truth simulator against the linear level, against an independent
// exact-kinematics reference for its second-order part, and its numerics
// (step halving, pulse bookkeeping, determinism, cost).
//
// Agreement measure: for each uncertainty at its Table 3.1 bound, over
// t = 1..90 min, |truth − linear| ≤ 1% |linear| + 1 m (docs/truth-vs-models.md). The truth is
// split into its odd part (x and −x: (r(x) − r(−x))/2, first order plus cubes)
// and its even part ((r(x) + r(−x))/2, the products of uncertainties the
// linear model drops by construction). The odd part must meet the bound for
// every uncertainty; the even part is measured and attributed.
#include "tests/unit/input_error_of.h"
#include "lib/truth/simulator.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <ctime>
#include <map>
#include <string>

#include "lib/alignment/alignment.h"
#include "lib/propagation/linear_model.h"
#include "lib/propagation/position_maps.h"
#include "lib/uncertainty/catalogue.h"

namespace insmc {
namespace {

constexpr double kRelativeTol = 0.01;  // 1% of the error …
constexpr double kAbsoluteTolM = 1.0;  // … plus 1 m

// Unoptimized builds (the ASan/UBSan job) run about a thousand times slower:
// there the sweeps check a representative subset; optimized builds check
// every uncertainty of both systems.
#ifdef NDEBUG
constexpr bool kFullSweeps = true;
#else
constexpr bool kFullSweeps = false;
#endif

/// Uncertainties the per-uncertainty sweeps check: all, or one or two per
/// group including every attributed second-order case.
std::vector<int> swept_uncertainties() {
  std::vector<int> all;
  if (kFullSweeps) {
    for (int i = 0; i < uncertainty_slot::kDim; ++i) all.push_back(i);
    return all;
  }
  return {uncertainty_slot::kAccelBias + 0, uncertainty_slot::kAccelScale + 2, uncertainty_slot::kBiasChangeAlign + 0, uncertainty_slot::kGyroDrift + 0,
          uncertainty_slot::kGyroDrift + 1, uncertainty_slot::kGyroMuyDrift + 0, uncertainty_slot::kMisalignAlign + 1, uncertainty_slot::kLatitudeError};
}

std::vector<double> minutes_1_to_90() {
  std::vector<double> t;
  for (int m = 1; m <= 90; ++m) t.push_back(60.0 * m);
  return t;
}

TruthOptions continuous_options(System s) {
  TruthOptions o;
  o.system = s;
  o.dv_pulse_mps = 0.0;  // the linear model has no quantization
  return o;
}

std::string system_name(System s) { return "system " + std::to_string(system_number(s)); }

UncertaintyVector single(int i, double scale = 1.0) {
  UncertaintyVector x = UncertaintyVector::Zero();
  x[i] = scale * default_bounds()[i];
  return x;
}

/// Worst-case measures of a − b over the times (b the reference).
struct Gap {
  double abs_m = 0.0;     ///< max |a − b|
  double rel = 0.0;       ///< max |a − b| / max(|b|, 1 m)
  double excess_m = -1e300;  ///< max (|a − b| − 1% |b| − 1 m): ≤ 0 passes
  void add(const Vec3& a, const Vec3& b) {
    const double d = (a - b).norm();
    abs_m = std::max(abs_m, d);
    rel = std::max(rel, d / std::max(b.norm(), 1.0));
    excess_m = std::max(excess_m, d - kRelativeTol * b.norm() - kAbsoluteTolM);
  }
};

/// S(t) of the linear level at minutes_1_to_90(), default options, computed
/// once per system.
const std::vector<Sensitivity3>& linear_maps(System s) {
  static const std::vector<Sensitivity3> maps[2] = {
      position_maps(System::kTheodolite, Fidelity::kLinear, ModelOptions{}, minutes_1_to_90()),
      position_maps(System::kGyrocompass, Fidelity::kLinear, ModelOptions{}, minutes_1_to_90())};
  return maps[system_number(s) - 1];
}

/// Linear-level position errors S(t) x at minutes_1_to_90().
std::vector<Vec3> linear_errors(System s, const UncertaintyVector& x) {
  std::vector<Vec3> out;
  for (const auto& map : linear_maps(s)) out.push_back(map * x);
  return out;
}

/// Second-order vertical error of a level misalignment θ_h at switch-over: the
/// z accelerometer reads −g cos θ, so the computer sees g θ²/2 less upward
/// force: δr_z = r0 (θ_h²/2)(1 − cos ω_s t) (down positive).
double vertical_tilt_term_m(const Vec3& c_prime, double t, const ModelOptions& m) {
  const double theta2 = c_prime.x() * c_prime.x() + c_prime.y() * c_prime.y();
  return m.radius_m * 0.5 * theta2 * (1.0 - std::cos(m.schuler_radps() * t));
}

TEST(TruthSimulator, EveryUncertaintyZeroStaysBelowOneMetreOverTwoHours) {
  const std::vector<double> times = uniform_times(7200.0, 10.0);
  for (System s : {System::kTheodolite, System::kGyrocompass}) {
    for (double dv : {0.0, 0.1 * kFtpsToMps}) {
      for (bool j2 : {false, true}) {
        TruthOptions o;
        o.system = s;
        o.dv_pulse_mps = dv;
        o.j2_gravity = j2;
        const TruthRun run = simulate_truth(o, UncertaintyVector::Zero(), times);
        double worst = 0.0;
        for (const Vec3& e : run.position_error_ap_m) worst = std::max(worst, e.norm());
        // Continuous: round-off only. Pulses of 0.1 ft/s: the computer's
        // velocity lags by the remainder (< half a pulse), ~0.5 m.
        EXPECT_LT(worst, dv > 0 ? 1.0 : 1e-6)
            << system_name(s) << " dv_pulse " << dv << " j2 " << j2;
        if (dv == 0.0 && !j2) {
          for (const Vec3& f : run.accel_error_ap_mps2)
            if (!std::isnan(f.x())) {
              EXPECT_LT(f.norm(), 1e-9);
            }
        }
      }
    }
  }
}

TEST(TruthSimulator, ZeroErrorAtOtherLatitudes) {
  const std::vector<double> times = uniform_times(7200.0, 600.0);
  for (double deg : {0.0, 30.0, -45.0, 60.0, 80.0}) {
    TruthOptions o = continuous_options(System::kGyrocompass);
    o.model.latitude_rad = deg * kDegToRad;
    const TruthRun run = simulate_truth(o, UncertaintyVector::Zero(), times);
    for (const Vec3& e : run.position_error_ap_m) EXPECT_LT(e.norm(), 1e-6) << deg << " deg";
  }
}

TEST(TruthSimulator, AgreesWithTheLinearLevelPerUncertainty) {
  // Every uncertainty at its bound, both systems, t = 1..90 min.
  //
  // Odd part (first order): must meet 1% + 1 m for every uncertainty. The
  // residual is ~0.17% (1 − g_s/g: the linear model uses g for the specific
  // force, the truth has gravity = gravitation − centrifugal at the site), up
  // to 0.4% for δL0 and δh (geocentric vs plumb-line latitude in their
  // initial conditions).
  //
  // truth(x) − linear(x) directly: three cases exceed 1% + 1 m, each by a
  // second-order term the linear model drops (the report's "neglecting
  // products of uncertainties", §3.1.4):
  //  * δf_x, δf_y (both systems): the leveling tilt θ = δf/g (1 mrad at 1 mg)
  //    makes the z accelerometer read −g cos θ: δr_z = r0 (θ²/2)(1 − cos ω_s t),
  //    6.4 m peak, while the horizontal errors nearly cancel (the bias is
  //    leveled out). Checked here after removing that term.
  //  * ω_doy, system 2: the gyrocompass azimuth error C'_z = −ω_doy/(ω_ie cos L0)
  //    (14 mrad at 10 meru) and the drift angle d_y compose as finite rotations:
  //    exp([C'×]) exp([d×]) = exp([(C' + d + ½ C' × d + …)×]), a tilt about x of
  //    ½ |C'_z| d_y growing with t, 168 m in y at 90 min against 3.4 km of
  //    first-order error. See SecondOrderPartIsTheFiniteRotationKinematics.
  const auto times = minutes_1_to_90();
  std::map<std::string, Gap> odd_per_group, raw_per_group;
  for (System s : {System::kTheodolite, System::kGyrocompass}) {
    const TruthOptions o = continuous_options(s);
    const auto& maps = linear_maps(s);
    for (int i : swept_uncertainties()) {
      const std::string what = system_name(s) + " " + std::string(catalogue()[i].name);
      const std::string group(catalogue()[i].group);
      const bool tilt_case = i == uncertainty_slot::kAccelBias + 0 || i == uncertainty_slot::kAccelBias + 1;
      const bool composition_case = s == System::kGyrocompass && i == uncertainty_slot::kGyroDrift + 1;
      const UncertaintyVector x = single(i);
      const TruthRun plus = simulate_truth(o, x, times), minus = simulate_truth(o, -x, times);
      Gap odd, raw, corrected;
      for (std::size_t k = 0; k < times.size(); ++k) {
        const Vec3 lin = maps[k] * x;
        const Vec3 r = plus.position_error_ap_m[k];
        const Vec3 odd_part = 0.5 * (r - minus.position_error_ap_m[k]);
        odd.add(odd_part, lin);
        odd_per_group[group].add(odd_part, lin);
        raw.add(r, lin);
        raw_per_group[group].add(r, lin);
        const Vec3 tilt(0.0, 0.0, vertical_tilt_term_m(plus.switchover_misalignment_rad, times[k], o.model));
        corrected.add(r - tilt, lin);
      }
      EXPECT_LE(odd.excess_m, 0.0) << what << ": odd part, worst |Δ| " << odd.abs_m << " m, relative "
                                   << odd.rel;
      if (tilt_case) {
        EXPECT_GT(raw.excess_m, 0.0) << what << " (the tilt term should show)";
        EXPECT_LE(corrected.excess_m, 0.0) << what << ": after the tilt term |Δ| " << corrected.abs_m;
        EXPECT_NEAR(raw.abs_m, o.model.radius_m * 1e-6, 0.05) << what;  // r0 θ², θ = 1 mrad
      } else if (composition_case) {
        EXPECT_GT(raw.abs_m, 100.0) << what;
        EXPECT_LT(raw.abs_m, 200.0) << what;
      } else {
        EXPECT_LE(raw.excess_m, 0.0) << what << ": worst |Δ| " << raw.abs_m << " m, relative " << raw.rel;
      }
    }
  }
  for (const auto& [group, gap] : odd_per_group)
    std::printf("  %-20s odd part vs linear: worst %8.3f m rel %.4f | truth vs linear: worst %8.3f m rel %.4f\n",
                group.c_str(), gap.abs_m, gap.rel, raw_per_group[group].abs_m, raw_per_group[group].rel);
}

TEST(TruthSimulator, EvenPartIsQuadraticInTheUncertainty) {
  // The even part r(x) + r(−x) is made of products of uncertainties: halving
  // x quarters it (to 2%: quartic terms and round-off).
  const auto times = minutes_1_to_90();
  const std::vector<int> cases =
      kFullSweeps ? std::vector<int>{uncertainty_slot::kAccelBias + 0, uncertainty_slot::kGyroDrift + 0, uncertainty_slot::kGyroDrift + 1,
                                     uncertainty_slot::kGyroMuyDrift + 0, uncertainty_slot::kMisalignAlign + 1}
                  : std::vector<int>{uncertainty_slot::kAccelBias + 0, uncertainty_slot::kGyroDrift + 1};
  for (System s : {System::kTheodolite, System::kGyrocompass}) {
    const TruthOptions o = continuous_options(s);
    for (int i : cases) {
      const auto even = [&](double scale) {
        const UncertaintyVector x = single(i, scale);
        const TruthRun p = simulate_truth(o, x, times), m = simulate_truth(o, -x, times);
        double worst = 0.0;
        for (std::size_t k = 0; k < times.size(); ++k)
          worst = std::max(worst, 0.5 * (p.position_error_ap_m[k] + m.position_error_ap_m[k]).norm());
        return worst;
      };
      const double full = even(1.0), half = even(0.5);
      ASSERT_GT(full, 0.5) << catalogue()[i].name;
      EXPECT_NEAR(full / half, 4.0, 0.08) << system_name(s) << " " << catalogue()[i].name;
    }
  }
}

/// An independent reference for the instrument and alignment errors: the
/// Schuler-loop ODE of the linear level driven by the exact specific-force
/// error of a platform turned by the finite rotations C_a^{a'}(t) =
/// A0 exp([d(t)×]) (A0 = switchover_attitude(C'), C' from the alignment maps
/// with the site's gravity g_s, d(t) the drift angles of (3.13)):
/// u = (I + A) C_{a'}^a(t) f^{a'}(t) + δf_nav − f^{a'}(t). It has every
/// product of rotation angles and no other nonlinearity. Only the uncertainties
/// that act through the platform and the accelerometers may be non-zero (δV,
/// δL0, δh, ξ, η zero).
std::vector<Vec3> rotation_reference(System s, const ModelOptions& m, const UncertaintyVector& x,
                                     double g_s, const std::vector<double>& times) {
  const LinearErrorModel linear(s, m);
  ModelOptions site = m;
  site.gravity_mps2 = g_s;
  const Vec3 c_prime = full_switchover_misalignment(s, site) * x;
  const Mat3 a0 = switchover_attitude(c_prime, Vec3(0, 0, -g_s));
  Vec3 bias = x.segment<3>(uncertainty_slot::kAccelBias);
  bias.head<2>() += x.segment<2>(uncertainty_slot::kBiasChangeConst) + x.segment<2>(uncertainty_slot::kBiasChangeAlign);
  const Vec3 scale = Vec3::Ones() + x.segment<3>(uncertainty_slot::kAccelScale);
  const auto forcing = [&](double t) {
    const Vec3 f_ap = C_ap_n(m.latitude_rad, m.earth_rate_radps * t) * Vec3(0, 0, -g_s);
    const Vec3 d = linear.drift_angles(t) * x;
    const double angle = d.norm();
    const Mat3 drift = Eigen::AngleAxisd(angle, angle > 0 ? Vec3(d / angle) : Vec3::UnitX()).toRotationMatrix();
    Sensitivity3 u = Sensitivity3::Zero();
    u.col(0) = scale.cwiseProduct((a0 * drift).transpose() * f_ap) + bias - f_ap;
    return u;
  };
  const auto maps = integrate_schuler_ode(forcing, Sensitivity3::Zero(), Sensitivity3::Zero(), times,
                                          m.schuler_radps(), 5.0);
  std::vector<Vec3> out;
  for (const auto& map : maps) out.push_back(map.col(0));
  return out;
}

/// x without the uncertainties that do not act through the platform and the
/// accelerometers (the rotation reference's domain).
UncertaintyVector rotation_part(UncertaintyVector x) {
  x.segment<3>(uncertainty_slot::kInitialVelocity).setZero();
  x.segment<2>(uncertainty_slot::kDeflection).setZero();
  x[uncertainty_slot::kLatitudeError] = 0.0;
  x[uncertainty_slot::kAltitudeError] = 0.0;
  return x;
}

TEST(TruthSimulator, SecondOrderPartIsTheFiniteRotationKinematics) {
  // The truth must agree with rotation_reference to ≤ 0.5 m + 0.1%, including
  // the 168 m of ω_doy in system 2 (what remains: MU acting on the misaligned
  // and drifted specific force, 3.9 m for g·MUY_x).
  const auto times = minutes_1_to_90();
  for (System s : {System::kTheodolite, System::kGyrocompass}) {
    const TruthOptions o = continuous_options(s);
    const std::vector<int> cases =
        kFullSweeps ? std::vector<int>{uncertainty_slot::kAccelBias + 0, uncertainty_slot::kAccelBias + 1, uncertainty_slot::kAccelScale + 2,
                                       uncertainty_slot::kBiasChangeAlign + 1, uncertainty_slot::kGyroDrift + 0, uncertainty_slot::kGyroDrift + 1,
                                       uncertainty_slot::kGyroDrift + 2, uncertainty_slot::kGyroMuDrift + 1, uncertainty_slot::kGyroMuyDrift + 0,
                                       uncertainty_slot::kMisalignAlign + 0, uncertainty_slot::kMisalignConst + 2, uncertainty_slot::kTheodolite}
                    : std::vector<int>{uncertainty_slot::kAccelBias + 1, uncertainty_slot::kGyroDrift + 1, uncertainty_slot::kGyroMuyDrift + 0};
    for (int i : cases) {
      const UncertaintyVector x = single(i);
      const TruthRun run = simulate_truth(o, x, times);
      const auto ref = rotation_reference(s, o.model, x, run.site_gravity_mps2, times);
      double worst = 0.0;
      for (std::size_t k = 0; k < times.size(); ++k) {
        const double d = (run.position_error_ap_m[k] - ref[k]).norm();
        EXPECT_LT(d, 0.5 + 1e-3 * ref[k].norm()) << system_name(s) << " " << catalogue()[i].name << " t "
                                                 << times[k] << " truth "
                                                 << run.position_error_ap_m[k].transpose() << " ref "
                                                 << ref[k].transpose();
        worst = std::max(worst, d);
      }
      std::printf("  truth vs exact-rotation reference  %s %-20s worst %.3f m\n", system_name(s).c_str(),
                  std::string(catalogue()[i].name).c_str(), worst);
    }
  }
}

/// Uniform within ±bound, from a fixed hashed stream.
UncertaintyVector random_at_bounds(std::uint64_t seed) {
  const NormalSource source = hashed_normal_source(seed);
  NormalDraws draws(source, 0);
  UncertaintyVector x;
  const UncertaintyVector b = default_bounds();
  for (int i = 0; i < uncertainty_slot::kDim; ++i) x[i] = b[i] * (2.0 * draws.next_uniform() - 1.0);
  return x;
}

TEST(TruthSimulator, AllUncertaintiesTogetherAgreeWithTheLinearLevel) {
  // Every uncertainty drawn uniformly within its bound. System 1: truth and
  // linear agree within 1% + 1 m. System 2: the finite-rotation product
  // ½ C'_z d_y of the gyrocompass azimuth error and the y drift (up to 171 m)
  // can exceed 1% of the error where the first-order errors partly cancel;
  // with that second-order part taken from the rotation reference
  // (linear(x) + rot(x_r) − linear(x_r), x_r = rotation_part(x)) every case
  // agrees within 1% + 1 m.
  const auto times = minutes_1_to_90();
  for (System s : {System::kTheodolite, System::kGyrocompass}) {
    const TruthOptions o = continuous_options(s);
    const std::vector<std::uint64_t> seeds =
        kFullSweeps ? std::vector<std::uint64_t>{1, 2, 3, 4} : std::vector<std::uint64_t>{4};
    for (std::uint64_t seed : seeds) {
      const UncertaintyVector x = random_at_bounds(seed);
      const TruthRun run = simulate_truth(o, x, times);
      const auto lin = linear_errors(s, x);
      const UncertaintyVector xr = rotation_part(x);
      const auto lin_r = linear_errors(s, xr);
      const auto rot_r = rotation_reference(s, o.model, xr, run.site_gravity_mps2, times);
      Gap raw, attributed;
      for (std::size_t k = 0; k < times.size(); ++k) {
        raw.add(run.position_error_ap_m[k], lin[k]);
        attributed.add(run.position_error_ap_m[k], lin[k] + rot_r[k] - lin_r[k]);
      }
      if (s == System::kTheodolite) {
        EXPECT_LE(raw.excess_m, 0.0) << system_name(s) << " seed " << seed;
      }
      EXPECT_LE(attributed.excess_m, 0.0) << system_name(s) << " seed " << seed;
      std::printf("  all together  %s seed %d  vs linear: worst %7.2f m rel %.4f%s | with 2nd order: %6.2f m "
                  "rel %.4f  (|linear| at 90 min %.0f m)\n",
                  system_name(s).c_str(), static_cast<int>(seed), raw.abs_m, raw.rel,
                  raw.excess_m > 0 ? " (>1%+1m)" : "", attributed.abs_m, attributed.rel, lin.back().norm());
    }
  }
}

TEST(TruthSimulator, AccelerometerOutputErrorAgreesWithTheLinearForcing) {
  // Δf^a (4.2) over each filter interval equals the mean of the linear
  // forcing u(t) over it (§4.1 with δg/g = −3 δh/r0), continuous output.
  const std::vector<double> times = uniform_times(1200.0, 10.0);
  for (System s : {System::kTheodolite, System::kGyrocompass}) {
    const TruthOptions o = continuous_options(s);
    const LinearErrorModel linear(s, o.model);
    for (std::uint64_t seed : {5u, 6u}) {
      const UncertaintyVector x = random_at_bounds(seed);
      const TruthRun run = simulate_truth(o, x, times);
      double worst = 0.0;
      for (std::size_t k = 1; k < times.size(); ++k) {
        const double t = times[k], tau = o.filter_interval_s;
        const Vec3 mean = (linear.forcing(t - tau) * x + 4.0 * (linear.forcing(t - 0.5 * tau) * x) +
                           linear.forcing(t) * x) / 6.0;
        const double d = (run.accel_error_ap_mps2[k] - mean).norm();
        worst = std::max(worst, d);
        // 1% plus 1 µg: the 0.17% of g_s/g and second-order tilt terms (g θ²/2).
        EXPECT_LT(d, 0.01 * mean.norm() + 1e-6 * kGravityMps2) << system_name(s) << " t " << t;
      }
      EXPECT_TRUE(std::isnan(run.accel_error_ap_mps2[0].x()));  // t = 0 < τ
      std::printf("  Δf vs linear forcing %s seed %d worst %.3g m/s² (%.3f µg)\n", system_name(s).c_str(),
                  static_cast<int>(seed), worst, worst / kUgToMps2);
    }
  }
}

TEST(TruthSimulator, HalvingTheStepChangesResultsByLessThanATenthOfAMetre) {
  const std::vector<double> times = uniform_times(7200.0, 10.0);
  const std::vector<System> systems = kFullSweeps ? std::vector<System>{System::kTheodolite, System::kGyrocompass}
                                                  : std::vector<System>{System::kGyrocompass};
  for (System s : systems) {
    for (double dv : {0.0, 0.1 * kFtpsToMps}) {
      TruthOptions o;
      o.system = s;
      o.dv_pulse_mps = dv;
      const UncertaintyVector x = random_at_bounds(7);
      const TruthRun coarse = simulate_truth(o, x, times);
      o.step_s *= 0.5;
      const TruthRun fine = simulate_truth(o, x, times);
      double worst = 0.0, worst_f = 0.0;
      for (std::size_t k = 0; k < times.size(); ++k) {
        worst = std::max(worst, (coarse.position_error_ap_m[k] - fine.position_error_ap_m[k]).norm());
        if (k > 0)
          worst_f = std::max(worst_f, (coarse.accel_error_ap_mps2[k] - fine.accel_error_ap_mps2[k]).norm());
      }
      EXPECT_LT(worst, 0.1) << system_name(s) << " dv " << dv;
      std::printf("  halving %g s -> %g s, %s, dv_pulse %.4f m/s: max |Δδr| %.2e m, max |ΔΔf| %.2e m/s²\n",
                  2 * o.step_s, o.step_s, system_name(s).c_str(), dv, worst, worst_f);
    }
  }
}

TEST(TruthSimulator, PulsesQuantizeWithTheRemainderCarried) {
  // The pulse counts add up to the integral of the continuous output to
  // within one pulse at every output time (the remainder is carried, never
  // dropped), and each interval's count is its continuous increment rounded
  // within one pulse.
  const std::vector<double> times = uniform_times(6000.0, 10.0);
  for (System s : {System::kTheodolite, System::kGyrocompass}) {
    TruthOptions o;
    o.system = s;
    const double w = o.dv_pulse_mps;
    const UncertaintyVector x = random_at_bounds(8);
    const TruthRun pulsed = simulate_truth(o, x, times);
    o.dv_pulse_mps = 0.0;
    const TruthRun cont = simulate_truth(o, x, times);
    Vec3 total_pulses = Vec3::Zero(), total_cont = Vec3::Zero();
    const double tau = o.filter_interval_s;
    for (std::size_t k = 1; k < times.size(); ++k) {
      // Continuous increment over the interval: (Δf + f̂) τ; f̂ is the same in both runs.
      const Vec3 cont_dv = (cont.accel_error_ap_mps2[k] - pulsed.accel_error_ap_mps2[k]) * tau +
                           w * pulsed.pulse_counts[k].cast<double>();
      total_pulses += w * pulsed.pulse_counts[k].cast<double>();
      total_cont += cont_dv;
      for (int a = 0; a < 3; ++a) {
        EXPECT_LE(std::abs(total_pulses[a] - total_cont[a]), w) << "axis " << a << " t " << times[k];
        EXPECT_LE(std::abs(w * pulsed.pulse_counts[k][a] - cont_dv[a]), 2 * w);
      }
    }
    // Position: the computer's velocity lags the continuous one by the
    // remainder, |ρ| < w/2, zero on average once pulses are dense: about a metre.
    double worst = 0.0;
    for (std::size_t k = 0; k < times.size(); ++k)
      worst = std::max(worst, (pulsed.position_error_ap_m[k] - cont.position_error_ap_m[k]).norm());
    EXPECT_LT(worst, 1.5) << system_name(s);
    std::printf("  0.1 ft/s pulses vs continuous output, %s, x at bounds: max |Δδr| %.2f m\n",
                system_name(s).c_str(), worst);
  }
}

TEST(TruthSimulator, PulsePhaseIsAnInitialVelocityError) {
  // A partial pulse ρ0 in the accumulator at switch-over is counted as a whole
  // pulse early: once pulses are dense (the z axis, ~320 per second) the
  // computer's velocity leads by ρ0 on average, a Schuler oscillation
  // ρ0 sin(ω_s t)/ω_s (12 m at half a pulse).
  const std::vector<double> times = uniform_times(5400.0, 60.0);
  TruthOptions o;
  const double w = o.dv_pulse_mps, ws = o.model.schuler_radps();
  const TruthRun zero = simulate_truth(o, UncertaintyVector::Zero(), times);
  o.pulse_phase = Vec3(0.0, 0.0, 0.4);
  const TruthRun phased = simulate_truth(o, UncertaintyVector::Zero(), times);
  for (std::size_t k = 0; k < times.size(); ++k) {
    // Counted velocity w N = V + ρ0 − ρ: the computer's velocity error is
    // ρ0 − ρ, on average +ρ0 along z (down).
    const double expected = 0.4 * w * std::sin(ws * times[k]) / ws;
    EXPECT_NEAR(phased.position_error_ap_m[k].z() - zero.position_error_ap_m[k].z(), expected, 0.3)
        << "t " << times[k];
  }
}

TEST(TruthSimulator, TorquerCommandsTurnThePlatform) {
  // Injection point 4: a constant torquer rate c turns the platform like a
  // drift that the alignment never saw: the linear level's drift term with
  // d = c t and no alignment change.
  const auto times = minutes_1_to_90();
  TruthOptions o = continuous_options(System::kTheodolite);
  const Vec3 c(0.0, 5.0 * kMeruToRadps, 2.0 * kMeruToRadps);
  o.torquer_command_radps = [c](double) { return c; };
  const TruthRun run = simulate_truth(o, UncertaintyVector::Zero(), times);
  const ModelOptions& m = o.model;
  const auto forcing = [&](double t) {
    const Vec3 gravity_ap = m.gravity_mps2 * C_ap_n(m.latitude_rad, m.earth_rate_radps * t).col(2);
    Sensitivity3 u = Sensitivity3::Zero();
    u.col(0) = -gravity_ap.cross(c * t);  // −(Z + D + Ψ) C g_e with D = paper_skew(c t)
    return u;
  };
  const auto ref = integrate_schuler_ode(forcing, Sensitivity3::Zero(), Sensitivity3::Zero(), times,
                                         m.schuler_radps(), 5.0);
  Gap gap;
  for (std::size_t k = 0; k < times.size(); ++k) gap.add(run.position_error_ap_m[k], ref[k].col(0));
  EXPECT_LE(gap.excess_m, 0.0) << gap.abs_m;
}

TEST(TruthSimulator, IsDeterministic) {
  const std::vector<double> times = uniform_times(3000.0, 10.0);
  TruthOptions o;
  o.effects = {parse_effect("sway"), parse_effect("velocity_random_walk"), parse_effect("switch_transient")};
  const NormalSource noise = hashed_normal_source(42);
  const UncertaintyVector x = random_at_bounds(9);
  const TruthRun a = simulate_truth(o, x, times, noise), b = simulate_truth(o, x, times, noise);
  for (std::size_t k = 0; k < times.size(); ++k) {
    EXPECT_EQ(a.position_error_ap_m[k], b.position_error_ap_m[k]);
    EXPECT_EQ(a.pulse_counts[k], b.pulse_counts[k]);
  }
}

TEST(TruthSimulator, OptionsAreValidated) {
  TruthOptions o;
  EXPECT_FALSE(test::thrown_by([&] { validate(o); }).has_value());
  o.step_s = 0.0;
  ASSERT_TRUE(test::thrown_by([&] { validate(o); }).has_value());
  EXPECT_EQ(test::thrown_by([&] { validate(o); })->field(), "step_s");
  o = TruthOptions{};
  o.pulse_phase.x() = 0.5;
  ASSERT_TRUE(test::thrown_by([&] { validate(o); }).has_value());
  o = TruthOptions{};
  o.dv_pulse_mps = -1.0;
  ASSERT_TRUE(test::thrown_by([&] { validate(o); }).has_value());
  EXPECT_EQ(test::thrown_by([&] { validate(o); })->field(), "dv_pulse_mps");
}

TEST(TruthSimulator, CostOfOneRun) {
  // Not a gate (timing thresholds stay out of unit tests): the figure the
  // truth level aims at (< 2 ms for 15 min test + 84 min flight, one core).
  const std::vector<double> times = uniform_times(99.0 * 60.0, 10.0);
  const TruthOptions o;
  UncertaintyVector x = random_at_bounds(10);
  const int runs = kFullSweeps ? 20 : 2;
  const std::clock_t c0 = std::clock();
  double sink = 0.0;
  for (int k = 0; k < runs; ++k) {
    x[0] = -x[0];
    sink += simulate_truth(o, x, times).position_error_ap_m.back().x();
  }
  const double cpu_ms = 1e3 * static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC / runs;
  std::printf("  one truth run (99 min, step %g s, outputs every 10 s, 0.1 ft/s pulses): %.3f ms CPU (%g)\n",
              o.step_s, cpu_ms, sink);
  EXPECT_TRUE(std::isfinite(sink));
}

}  // namespace
}  // namespace insmc

namespace insmc {
namespace {

TEST(TruthSimulator, TimeDomainAlignmentSettlesToTheSteadyState) {
  // The loops simulated for 3 h from a coarse error leave the platform where
  // the steady state puts it: the navigation error agrees within 1 cm; after
  // 2 min the unsettled level loops of system 1 leave a visible error, and the
  // alignment's averaged commands equal (5.14) of the steady state.
  const auto times = minutes_1_to_90();
  for (System s : {System::kTheodolite, System::kGyrocompass}) {
    TruthOptions steady = continuous_options(s);
    TruthOptions loops = steady;
    loops.alignment_loops = AlignmentLoopSettings{};
    loops.alignment_loops->duration_s = 3 * 3600.0;
    const UncertaintyVector x = random_at_bounds(5);
    const TruthRun a = simulate_truth(steady, x, times), b = simulate_truth(loops, x, times);
    double worst = 0.0;
    for (std::size_t k = 0; k < times.size(); ++k)
      worst = std::max(worst, (a.position_error_ap_m[k] - b.position_error_ap_m[k]).norm());
    EXPECT_LT(worst, 0.01) << system_name(s);
    // The commands and accelerometer outputs the alignment saw: (5.14),
    // (5.19) of the steady state at the site's g_s, and the loops' averages.
    ModelOptions site = steady.model;
    site.gravity_mps2 = a.site_gravity_mps2;
    const Sensitivity3 c = full_steady_state_misalignment(s, site);
    EXPECT_LT((a.alignment_command_radps - torquer_commands(c, site) * x).norm(), 1e-12);
    EXPECT_LT((a.alignment_accel_output_mps2 - alignment_accelerometer_outputs(c, site) * x).norm(), 1e-12);
    EXPECT_LT((b.alignment_command_radps - a.alignment_command_radps).norm(), 1e-4 * kMeruToRadps) << system_name(s);
    EXPECT_LT((b.alignment_accel_output_mps2 - a.alignment_accel_output_mps2).norm(), 1e-8) << system_name(s);
    loops.alignment_loops->duration_s = 120.0;
    const TruthRun early = simulate_truth(loops, x, times);
    EXPECT_GT((early.switchover_misalignment_rad - a.switchover_misalignment_rad).norm(), 1e-6) << system_name(s);
  }
}

}  // namespace
}  // namespace insmc
