#include "lib/common/enum_names.h"
#include "lib/imu/strapdown.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "lib/common/assert.h"
#include "lib/truth/earth_model.h"
#include "lib/truth/simulator.h"

namespace insmc {
namespace {

/// Times on the file's clock closer than this are the same instant: sample
/// times k / rate carry round-off of ~1e-12 s; real sample intervals are
/// longer than 1e-5 s.
constexpr double kTimeTolS = 1e-7;

/// The outputs and the starts of their filter intervals, sorted, merged
/// within kTimeTolS (as the truth simulator's stops).
std::vector<double> stop_times(const std::vector<double>& outputs, double tau) {
  std::vector<double> stops{0.0};
  for (double t : outputs) {
    stops.push_back(t);
    if (t - tau >= -kTimeTolS) stops.push_back(std::max(0.0, t - tau));
  }
  std::sort(stops.begin(), stops.end());
  std::vector<double> unique;
  for (double t : stops)
    if (unique.empty() || t - unique.back() > kTimeTolS) unique.push_back(t);
  return unique;
}

std::size_t find_stop(const std::vector<double>& stops, double t) {
  const auto it = std::lower_bound(stops.begin(), stops.end(), t - kTimeTolS);
  INSMC_ASSERT(it != stops.end() && std::abs(*it - t) <= kTimeTolS, "stop {} missing", t);
  return static_cast<std::size_t>(it - stops.begin());
}

/// First sample index with t_k ≥ t − kTimeTolS (size() if none).
std::size_t first_sample_at(const ImuSamples& s, double t) {
  return static_cast<std::size_t>(std::lower_bound(s.t_s.begin(), s.t_s.end(), t - kTimeTolS) - s.t_s.begin());
}

/// exp of the body-frame rotation vector θ as a unit quaternion
/// (cos |θ|/2, sin(|θ|/2) θ/|θ|): the standard strapdown attitude update for
/// a rate constant over the step (exact, no coning within one sample).
Eigen::Quaterniond rotation_quaternion(const Vec3& theta) {
  const double a = theta.norm();
  // sin(a/2)/a by its series below 1e-4 rad (error < a⁴/3840 ≈ 3e-20).
  const double k = a < 1e-4 ? 0.5 - a * a / 48.0 : std::sin(0.5 * a) / a;
  return Eigen::Quaterniond(std::cos(0.5 * a), k * theta.x(), k * theta.y(), k * theta.z());
}

/// The navigation computer's position and velocity in i under the linear
/// computed gravitation G_c = −w² r (3.21) and a specific force a0 + a1 s
/// (s the time since the step began): the exact solution of
/// r̈ = −w² r + a0 + a1 s over one step (an isotropic harmonic oscillator).
struct SchulerOscillator {
  double w = 0.0;  ///< sqrt(μ/R³) [rad/s]

  void step(double h, const Vec3& a0, const Vec3& a1, Vec3& r, Vec3& v) const {
    const double x = w * h, s = std::sin(x);
    const double half = std::sin(0.5 * x);
    const double one_minus_cos = 2.0 * half * half;  // 1 − cos x without cancellation
    // x − sin x by its series below 1e-2 (next term x¹¹/11! < 1e-29).
    const double x2 = x * x;
    const double x_minus_sin = x < 1e-2 ? x * x2 / 6.0 * (1.0 - x2 / 20.0 * (1.0 - x2 / 42.0 * (1.0 - x2 / 72.0)))
                                        : x - s;
    const double w2 = w * w;
    // Homogeneous part r cos + v sin/w, and the particular parts of a0
    // ((1 − cos)/w²) and of a1 s ((s − sin(ws)/w)/w²); the small increments
    // are summed before they meet r (r ~ 6e6 m).
    const Vec3 dr = -one_minus_cos * r + (s / w) * v + (one_minus_cos / w2) * a0 + (x_minus_sin / (w2 * w)) * a1;
    const Vec3 dv = -one_minus_cos * v - (w * s) * r + (s / w) * a0 + (one_minus_cos / w2) * a1;
    r += dr;
    v += dv;
  }
};

/// R_z(angle) v: an earth-fixed vector in i after the earth has turned by angle.
Vec3 turned_by_earth(double angle_rad, const Vec3& v) { return earth_rotation(angle_rad) * v; }

std::string describe_duration(double s) { return fmt::format("{:.6g} s", s); }

}  // namespace

namespace {
constexpr EnumName<GyroBiasMode> kGyroBiasModeNames[] = {{GyroBiasMode::kRemove, "remove"}, {GyroBiasMode::kKeep, "keep"}};
}  // namespace

std::string_view to_string(GyroBiasMode m) { return name_of<GyroBiasMode>(kGyroBiasModeNames, m); }

GyroBiasMode parse_gyro_bias_mode(std::string_view text, std::string_view field) {
  if (const auto m = value_named<GyroBiasMode>(kGyroBiasModeNames, text)) return *m;
  throw InputError(std::string(field), std::string(text),
                   "must be remove (subtract the bias estimated during alignment) or keep");
}

void validate(const StrapdownOptions& o) {
  const auto bad = [](const char* field, double v, const char* unit, const char* allowed) {
    return InputError(field, fmt::format("{}{}", v, unit), allowed);
  };
  if (!(std::abs(o.latitude_rad) < 0.5 * std::numbers::pi))
    throw bad("--latitude", o.latitude_rad / kDegToRad, "deg", "must lie strictly between -90deg and 90deg");
  if (!(o.altitude_m >= -1e4 && o.altitude_m <= 1e5))
    throw bad("--altitude", o.altitude_m, "m", "must lie in [-10km, 100km]");
  if (!std::isfinite(o.azimuth_rad)) throw bad("--azimuth", o.azimuth_rad, "rad", "must be finite");
  if (!(o.align_duration_s > 0) || !std::isfinite(o.align_duration_s))
    throw bad("--align-duration", o.align_duration_s, "s", "must be finite and > 0");
  if (!(o.test_duration_s > 0) || !std::isfinite(o.test_duration_s))
    throw bad("--test-duration", o.test_duration_s, "s", "must be finite and > 0");
  if (!(o.nav_duration_s > 0) || !std::isfinite(o.nav_duration_s))
    throw bad("--nav-duration", o.nav_duration_s, "s", "must be finite and > 0");
  if (!(o.output_interval_s > 0) || !(o.output_interval_s <= o.test_duration_s))
    throw bad("--interval", o.output_interval_s, "s", "must be > 0 and no longer than the test run");
  if (!(o.earth_rate_radps > 0 && o.gravity_mps2 > 0 && o.radius_m > 0))
    throw bad("earth constants", o.radius_m, "m", "earth rate, g and r0 must be > 0");
}

StationarySite stationary_site(const StrapdownOptions& o) {
  const GravityField field = model_gravity_field(o.gravity_mps2, o.radius_m, 0.0);
  const double w = o.earth_rate_radps, radius = o.radius_m + o.altitude_m;
  StationarySite site;
  site.position_e_m = position_for_plumb_latitude(field, w, radius, o.latitude_rad);
  site.C_e_n = C_i_n(o.latitude_rad, 0.0);  // (3.3) at λ = 0
  // r̈ = G + f for the site turning with the earth: f = −ω × (ω × r) − G.
  const Vec3 centripetal = -w * w * Vec3(site.position_e_m.x(), site.position_e_m.y(), 0.0);
  const Vec3 f_e = centripetal - field.gravitation(site.position_e_m);
  site.specific_force_n_mps2 = site.C_e_n.transpose() * f_e;
  site.earth_rate_n_radps = site.C_e_n.transpose() * Vec3(0.0, 0.0, w);
  site.gravity_mps2 = f_e.norm();
  site.schuler_radps = std::sqrt(field.mu_m3ps2 / (radius * radius * radius));
  return site;
}

Mat3 C_n_b_from_euler(double roll_rad, double pitch_rad, double heading_rad) {
  return (Eigen::AngleAxisd(heading_rad, Vec3::UnitZ()) * Eigen::AngleAxisd(pitch_rad, Vec3::UnitY()) *
          Eigen::AngleAxisd(roll_rad, Vec3::UnitX()))
      .toRotationMatrix();
}

StrapdownAlignment align_stationary(const Vec3& mean_accel_b, const Vec3& mean_gyro_b, std::size_t samples,
                                    const StrapdownOptions& o, const StationarySite& site,
                                    std::string_view source) {
  const double f = mean_accel_b.norm();
  if (!(f >= 0.5 * kGravityMps2 && f <= 2.0 * kGravityMps2))
    throw InputError(fmt::format(
        "{}: mean specific force over the alignment window is {:.6g} m/s2 ({:.4g} g): a stationary IMU measures "
        "about 1 g; check --accel-unit and --accel-columns",
        source, f, f / kGravityMps2));
  if (!(mean_gyro_b.norm() <= 0.5))
    throw InputError(fmt::format(
        "{}: mean angular rate over the alignment window is {:.6g} rad/s: a stationary IMU senses the earth rate "
        "(7.3e-5 rad/s) plus its bias; check --gyro-unit and --gyro-columns, or the base moved",
        source, mean_gyro_b.norm()));
  StrapdownAlignment a;
  a.mean_accel_b_mps2 = mean_accel_b;
  a.mean_gyro_b_radps = mean_gyro_b;
  a.samples = samples;
  // Leveling: the body's specific force f^b = C_b^n (0, 0, −g) =
  // g (sin θ, −cos θ sin φ, −cos θ cos φ) for the 3-2-1 angles; solving for
  // φ, θ puts the measured mean force on the computed vertical, which is what
  // the leveling loops do (2.9)–(2.10): horizontal biases become a tilt.
  a.roll_rad = std::atan2(-mean_accel_b.y(), -mean_accel_b.z());
  a.pitch_rad = std::atan2(mean_accel_b.x(), std::hypot(mean_accel_b.y(), mean_accel_b.z()));
  if (std::abs(a.pitch_rad) > 80.0 * kDegToRad)
    throw InputError(fmt::format("{}: the sensor x axis is {:.4g} deg from the horizontal: --azimuth (heading of "
                                 "sensor x) is undefined within 10 deg of the vertical; relabel the axes with "
                                 "--gyro-columns and --accel-columns",
                                 source, a.pitch_rad / kDegToRad));
  // Azimuth from the user: system 1's theodolite (2.11).
  const Mat3 C_n_b = C_n_b_from_euler(a.roll_rad, a.pitch_rad, o.azimuth_rad);
  a.C_ap_b = C_n_b;  // a' = n at t = 0 (frames.h)
  // The aligned body must sense the earth rate C_b^n ω_ie^n; the rest of the
  // mean is the gyro bias (the window's mean, so it includes the mean of any
  // in-run drift over the window).
  a.gyro_bias_b_radps = mean_gyro_b - C_n_b.transpose() * site.earth_rate_n_radps;
  return a;
}

int runs_available(const ImuSamples& s, const StrapdownOptions& o) {
  if (s.size() < 2) return 0;
  return static_cast<int>(std::floor((s.covered_s() + kTimeTolS) / o.run_duration_s()));
}

StrapdownRun run_strapdown(const ImuSamples& s, double start_s, const StrapdownOptions& o) {
  validate(o);
  INSMC_ASSERT(s.size() >= 2, "{} samples", s.size());
  const double T = o.test_duration_s, tau = o.output_interval_s, end = T + o.nav_duration_s;
  const std::size_t k_start = first_sample_at(s, start_s);
  const std::size_t k_switch = first_sample_at(s, start_s + o.align_duration_s);
  const double needed_s = start_s + o.run_duration_s();
  if (k_switch >= s.size() || k_switch == k_start || s.covered_s() < s.t_s[k_switch] + end - kTimeTolS)
    throw InputError(fmt::format(
        "{}: the samples cover {}; the run starting at {} needs alignment {} + test {} + navigation {} = up to {}; "
        "shorten --nav-duration or --align-duration",
        s.source, describe_duration(s.covered_s()), describe_duration(start_s),
        describe_duration(o.align_duration_s), describe_duration(T), describe_duration(o.nav_duration_s),
        describe_duration(needed_s)));

  StrapdownRun run;
  run.switch_time_s = s.t_s[k_switch];
  const StationarySite site = stationary_site(o);

  // ---- alignment window [start, switch): interval-weighted means ------------
  Vec3 sum_f = Vec3::Zero(), sum_w = Vec3::Zero();
  double span = 0.0;
  for (std::size_t k = k_start; k < k_switch; ++k) {
    const double h = s.end_s(k) - s.t_s[k];
    sum_f += h * s.accel_b_mps2[k];
    sum_w += h * s.gyro_b_radps[k];
    span += h;
  }
  run.alignment = align_stationary(sum_f / span, sum_w / span, k_switch - k_start, o, site, s.source);
  const Vec3 gyro_correction =
      o.gyro_bias == GyroBiasMode::kRemove ? run.alignment.gyro_bias_b_radps : Vec3::Zero();

  // ---- navigation computer ----------------------------------------------------
  const Mat3 C_ap_i = insmc::C_ap_i(o.latitude_rad);  // (3.2), from the user's L0
  const Mat3 C_i_ap = C_ap_i.transpose();
  const SchulerOscillator oscillator{site.schuler_radps};
  const double w_ie = o.earth_rate_radps;
  // (3.22)–(3.23): the computer starts at the site with the earth's velocity.
  Vec3 r_c = site.position_e_m;
  Vec3 v_c = Vec3(0.0, 0.0, w_ie).cross(r_c);
  Eigen::Quaterniond q_ap_b(run.alignment.C_ap_b);
  q_ap_b.normalize();

  run.t_s = uniform_times(end, tau, false);
  // k τ carries round-off (9000 × 0.1 s ≠ 900 s): put the grid point at T
  // exactly on T, so the record's test/nav split (t ≤ T) sees it as the test's end.
  for (double& t_out : run.t_s)
    if (std::abs(t_out - T) <= kTimeTolS) t_out = T;
  const std::vector<double> stops = stop_times(run.t_s, tau);
  std::vector<Vec3> segment_velocity(stops.size(), Vec3::Zero());  // ∫ f^a dt since the previous stop
  std::vector<Vec3> stop_error(stops.size(), Vec3::Zero());
  Vec3 velocity = Vec3::Zero();

  // One step of length h within a sample: body rate ω and force f constant.
  const auto step = [&](double h, const Vec3& omega_b, const Vec3& f_b) {
    const Mat3 C_ap_b = q_ap_b.toRotationMatrix();
    // The force turns with the body within the step: f^a(s) = C (f + s ω × f)
    // to first order in ωh (standard rotation compensation of the velocity
    // increment, ½ Δθ × Δv).
    const Vec3 f_a = C_ap_b * f_b;
    const Vec3 df_a = C_ap_b * omega_b.cross(f_b);
    velocity += h * f_a + 0.5 * h * h * df_a;
    // r̈_c = G_c(r_c) + Ĉ_a^i f^a (3.20)–(3.21).
    oscillator.step(h, C_i_ap * f_a, C_i_ap * df_a, r_c, v_c);
    q_ap_b = q_ap_b * rotation_quaternion(h * omega_b);
    q_ap_b.normalize();
  };

  std::size_t k = k_switch;
  double t = 0.0;  // since the switch; within sample k's interval
  for (std::size_t stop = 1; stop < stops.size(); ++stop) {
    const double target = stops[stop];
    while (true) {
      INSMC_ASSERT(k < s.size(), "sample {} beyond the {} samples at t = {}", k, s.size(), t);
      const double sample_end = s.end_s(k) - run.switch_time_s;
      const Vec3 omega = s.gyro_b_radps[k] - gyro_correction;
      if (sample_end <= target + kTimeTolS) {  // the rest of the sample lies before the stop
        if (sample_end > t) step(sample_end - t, omega, s.accel_b_mps2[k]);
        t = sample_end;
        ++k;
        if (sample_end >= target - kTimeTolS) break;
      } else {  // the stop falls inside the sample: split it
        step(target - t, omega, s.accel_b_mps2[k]);
        t = target;
        break;
      }
    }
    segment_velocity[stop] = velocity;
    velocity.setZero();
    // δr^{a'} = C_i^{a'} (r_c − r), r the site turned by the earth (4.5).
    stop_error[stop] = C_ap_i * (r_c - turned_by_earth(w_ie * target, site.position_e_m));
  }

  // ---- outputs ------------------------------------------------------------------
  const double cosL = std::cos(o.latitude_rad), sinL = std::sin(o.latitude_rad);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  run.accel_error_ap_mps2.resize(run.t_s.size());
  run.position_error_ap_m.resize(run.t_s.size());
  for (std::size_t j = 0; j < run.t_s.size(); ++j) {
    const double tj = run.t_s[j];
    const std::size_t stop_end = find_stop(stops, tj);
    run.position_error_ap_m[j] = stop_error[stop_end];
    if (tj < tau - kTimeTolS) {
      run.accel_error_ap_mps2[j] = Vec3::Constant(nan);
      continue;
    }
    const std::size_t stop_begin = find_stop(stops, std::max(0.0, tj - tau));
    Vec3 dv = Vec3::Zero();
    for (std::size_t m = stop_begin + 1; m <= stop_end; ++m) dv += segment_velocity[m];
    const double ta = stops[stop_begin], tb = stops[stop_end], width = tb - ta;
    // (4.1): f̂^{a'} = C_i^{a'} C_n^i(t) (0, 0, −g_s), C_n^i(t) e_z = −(cL cos ω_ie t, cL sin ω_ie t, sL)
    // (3.3), averaged over (ta, tb] in closed form.
    const Vec3 mean_up(cosL * (std::sin(w_ie * tb) - std::sin(w_ie * ta)) / (w_ie * width),
                       cosL * (std::cos(w_ie * ta) - std::cos(w_ie * tb)) / (w_ie * width), sinL);
    const Vec3 f_hat = site.gravity_mps2 * (C_ap_i * mean_up);
    run.accel_error_ap_mps2[j] = dv / width - f_hat;  // Δf^a (4.2)
  }
  return run;
}

}  // namespace insmc
