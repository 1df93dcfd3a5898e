#include "lib/truth/simulator.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "lib/alignment/alignment.h"
#include "lib/common/assert.h"
#include "lib/truth/earth_model.h"
#include "lib/units/units.h"

namespace insmc {
namespace {

using State = Eigen::Matrix<double, 16, 1>;
// State layout: platform quaternion q = C_a^i (w, x, y, z); velocity and
// double-integral increments of the accelerometer outputs since the step
// began (a frame); navigation error δr, δv (i frame, continuous-output part).
constexpr int kQ = 0, kDV = 4, kDW = 7, kDR = 10, kDVel = 13;

Mat3 quaternion_matrix(const Eigen::Vector4d& q) {
  const double w = q[0], x = q[1], y = q[2], z = q[3];
  Mat3 m;
  m << 1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y),  //
      2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x),    //
      2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y);
  return m;
}

/// Unit quaternion of a rotation matrix (Shepperd via Eigen).
Eigen::Vector4d matrix_quaternion(const Mat3& m) {
  const Eigen::Quaterniond q(m);
  return Eigen::Vector4d(q.w(), q.x(), q.y(), q.z());
}

/// exp([θ×]): the rotation by the rotation vector θ (Rodrigues, exact).
Mat3 rotation(const Vec3& theta) {
  const double a = theta.norm();
  Mat3 k;
  k << 0.0, -theta.z(), theta.y(), theta.z(), 0.0, -theta.x(), -theta.y(), theta.x(), 0.0;
  if (a < 1e-8) return Mat3::Identity() + k + 0.5 * k * k;  // series to O(a³)
  return Mat3::Identity() + std::sin(a) / a * k + (1.0 - std::cos(a)) / (a * a) * k * k;
}

/// The smallest rotation R with R u = v (unit vectors, u·v > −1).
Mat3 minimal_rotation(const Vec3& u, const Vec3& v) {
  const Vec3 k = u.cross(v);
  Mat3 kx;
  kx << 0.0, -k.z(), k.y(), k.z(), 0.0, -k.x(), -k.y(), k.x(), 0.0;
  return Mat3::Identity() + kx + kx * kx / (1.0 + u.dot(v));
}

/// R_z(angle) v with (c, s) = (cos, sin) of the angle.
Vec3 rotate_z(double c, double s, const Vec3& v) {
  return Vec3(c * v.x() - s * v.y(), s * v.x() + c * v.y(), v.z());
}

/// The rounding quantizer's remainder a − w round(a/w) ∈ [−w/2, w/2).
double remainder_of(double a, double w) { return a - w * std::floor(a / w + 0.5); }

/// ∫_{t0}^{t0+h} ρ(a(s)) ds for the accumulator a(s) linear from a0 to a1:
/// ρ has the antiderivative ρ²/2 in a (continuous across the jumps).
double integral_of_remainder_linear(double a0, double a1, double w, double h) {
  if (std::abs(a1 - a0) < 1e-9 * w) return h * remainder_of(0.5 * (a0 + a1), w);
  const double r0 = remainder_of(a0, w), r1 = remainder_of(a1, w);
  return h * 0.5 * (r1 * r1 - r0 * r0) / (a1 - a0);
}

/// Pulses crossed per step above which the dense-pulse formula is used.
constexpr int kMaxExactCrossings = 24;

/// ∫_0^h ρ(a(s)) ds over one step, ρ the quantizer remainder of the
/// accumulator a(s) = a0 + ΔV(s), given ΔV(h) = dv and ∫_0^h ΔV = dw (both
/// exact from the integrator). ∫ρ = ∫a − w ∫Q(a) with ∫a exact; ∫Q(a) from the
/// crossing times of the quadratic ΔV(s) that matches dv and dw when few
/// pulses fall in the step (error O(f̈ h⁴) per crossing). With many pulses the
/// crossings are dense and ρ(a(s)) is insensitive to the path between the
/// end points: ∫ρ(a_lin) of the linear path, whose error averages out.
double integral_of_remainder(double a0, double dv, double dw, double h, double w) {
  const double exact_integral = h * a0 + dw;
  const double a1 = a0 + dv;
  const auto q = [w](double a) { return std::floor(a / w + 0.5); };
  // ΔV(s) = α s + β s²: α h + β h² = dv, α h²/2 + β h³/3 = dw.
  const double beta = (3.0 * dv * h - 6.0 * dw) / (h * h * h);
  const double alpha = dv / h - beta * h;
  double pieces[3] = {0.0, h, h};
  int n_pieces = 1;
  if (beta != 0.0) {
    const double s_ext = -alpha / (2.0 * beta);
    if (s_ext > 0.0 && s_ext < h) {
      pieces[1] = s_ext;
      n_pieces = 2;
    }
  }
  const auto a_at = [&](double s) { return a0 + (alpha + beta * s) * s; };
  // Counted in double: a huge or non-finite level count must take the
  // linear path, never an int conversion that wraps (the level loop below
  // is bounded by kMaxExactCrossings only through this test).
  double crossings = 0.0;
  for (int k = 0; k < n_pieces; ++k) crossings += std::abs(q(a_at(pieces[k + 1])) - q(a_at(pieces[k])));
  if (!(crossings <= kMaxExactCrossings)) return integral_of_remainder_linear(a0, a1, w, h);
  double integral_q = 0.0;
  for (int k = 0; k < n_pieces; ++k) {
    const double sa = pieces[k], sb = pieces[k + 1];
    const double qa = q(a_at(sa)), qb = q(a_at(sb));
    integral_q += qa * (sb - sa);
    const double direction = qb > qa ? 1.0 : -1.0;
    // An integer count (at most kMaxExactCrossings): stepping a double
    // level by ±1 would stall where the levels exceed 2^53.
    const int levels = static_cast<int>(std::abs(qb - qa));
    for (int i = 0; i < levels; ++i) {
      const double level_q = qa + i * direction;
      // Crossing of the level between level_q and level_q + direction.
      const double level = (level_q + 0.5 * direction) * w;
      // β s² + α s + (a0 − level) = 0, the root in [sa, sb].
      const double c = a0 - level;
      double root;
      if (std::abs(beta) * h < 1e-12 * std::abs(alpha)) {
        root = -c / alpha;
      } else {
        const double disc = std::max(0.0, alpha * alpha - 4.0 * beta * c);
        const double sq = std::sqrt(disc);
        const double qq = -0.5 * (alpha + (alpha >= 0 ? sq : -sq));
        const double r1 = qq / beta, r2 = (qq != 0.0) ? c / qq : r1;
        // The piece is monotone: one root lies in it (up to round-off).
        const double slack = 1e-9 * h;
        root = (r1 >= sa - slack && r1 <= sb + slack) ? r1 : r2;
      }
      root = std::clamp(root, sa, sb);
      integral_q += direction * (sb - root);
    }
  }
  return exact_integral - w * integral_q;
}

/// Turns the platform quaternion of `y` by the body-frame rotation vector θ.
void turn_platform(State& y, const Vec3& theta) {
  const double a = theta.norm();
  if (a == 0.0) return;
  const Vec3 axis = theta / a;
  const double c = std::cos(0.5 * a), s = std::sin(0.5 * a);
  const Eigen::Vector4d q = y.segment<4>(kQ);
  const Vec3 qv = q.segment<3>(1), r = s * axis;
  Eigen::Vector4d out;  // q ⊗ (cos ½a, sin ½a axis)
  out[0] = q[0] * c - qv.dot(r);
  out.segment<3>(1) = q[0] * r + c * qv + qv.cross(r);
  y.segment<4>(kQ) = out.normalized();
}

/// Everything constant during a run, and the right-hand side of the ODE.
struct Dynamics {
  // earth and truth
  Vec3 site_position_e = Vec3::Zero();
  Vec3 site_gravitation_e = Vec3::Zero();  ///< incl. the deflection anomaly
  Vec3 site_specific_force_e = Vec3::Zero();
  // platform and instruments
  Mat3 mass_unbalance = Mat3::Zero();  ///< MU (3.10)
  Vec3 drift_ai = Vec3::Zero();        ///< ω_AI (3.8)
  Vec3 scale = Vec3::Ones();           ///< 1 + a_k
  Vec3 nav_bias = Vec3::Zero();        ///< δf + ∂f (3.18) + steps
  Vec3 quadratic = Vec3::Zero();
  double anisoelastic = 0.0;
  const std::vector<ExponentialTerm>* bias_transients = nullptr;
  const std::vector<ExponentialTerm>* drift_transients = nullptr;
  const std::function<Vec3(double)>* torquer = nullptr;
  const AccelCompensation* compensation = nullptr;
  bool compensating = false;  ///< the current step lies after compensation->start_s
  // computer
  Mat3 c_hat = Mat3::Identity();   ///< Ĉ_a^i (3.20)
  GravityField computer_field;
  double computer_radius = 0.0;    ///< r0 + δh (external altitude)
  double computer_mu_over_r3 = 0.0;
  Vec3 quantization_offset_i = Vec3::Zero();  ///< Ĉ P, held over a step

  Vec3 computer_gravitation(const Vec3& r_c) const {
    if (computer_field.j2 == 0.0) return -computer_mu_over_r3 * r_c;
    const double n = r_c.norm();
    return n / computer_radius * computer_field.gravitation(computer_radius / n * r_c);
  }

  void derivative(double t, double c, double s, const State& y, State& dy) const {
    const Eigen::Vector4d q = y.segment<4>(kQ);
    const Mat3 c_i_a_t = quaternion_matrix(q).transpose();
    const Vec3 f_i = rotate_z(c, s, site_specific_force_e);
    const Vec3 f_a = c_i_a_t * f_i;
    Vec3 f_m = scale.cwiseProduct(f_a) + nav_bias + quadratic.cwiseProduct(f_a.cwiseAbs2());
    Vec3 omega = drift_ai + mass_unbalance * f_a;
    if (anisoelastic != 0.0)
      omega += anisoelastic * Vec3(f_a.y() * f_a.z(), f_a.z() * f_a.x(), f_a.x() * f_a.y());
    for (const ExponentialTerm& e : *bias_transients) f_m += std::exp(-t / e.time_constant_s) * e.amplitude;
    for (const ExponentialTerm& e : *drift_transients) omega += std::exp(-t / e.time_constant_s) * e.amplitude;
    if (*torquer) omega += (*torquer)(t);
    // q̇ = ½ q ⊗ (0, ω): the platform turns at ω_ia^a (3.6)–(3.7).
    const double qw = q[0];
    const Vec3 qv = q.segment<3>(1);
    dy[kQ] = -0.5 * qv.dot(omega);
    dy.segment<3>(kQ + 1) = 0.5 * (qw * omega + qv.cross(omega));
    dy.segment<3>(kDV) = f_m;
    dy.segment<3>(kDW) = y.segment<3>(kDV);
    // δv̇ = G_c(r_c) − G(r) + Ĉ f_m − f^i: the computer's r̈_c minus the true r̈.
    const Vec3 r_true = rotate_z(c, s, site_position_e);
    const Vec3 r_c = r_true + y.segment<3>(kDR) - quantization_offset_i;
    dy.segment<3>(kDVel) = computer_gravitation(r_c) - rotate_z(c, s, site_gravitation_e) +
                           c_hat * f_m - f_i;
    if (compensating) dy.segment<3>(kDVel) += c_hat * compensation->at(t);  // point 2 (fig. 5.1)
    dy.segment<3>(kDR) = y.segment<3>(kDVel);
  }
};

struct SwayState {
  Vec3 position_n = Vec3::Zero(), velocity_n = Vec3::Zero();
};

SwayState sway_at(const std::vector<SwayComponent>& sway, double t) {
  SwayState s;
  for (const SwayComponent& c : sway) {
    const double w = 2.0 * std::numbers::pi / c.period_s, arg = w * t + c.phase_rad;
    s.position_n += std::sin(arg) * c.amplitude_n_m;
    s.velocity_n += w * std::cos(arg) * c.amplitude_n_m;
  }
  return s;
}

/// Times at which the integration stops: the outputs, the starts of their
/// filter intervals and the `events` (compensation start, reset) before the
/// last output, merged within 1e-9 s.
std::vector<double> stop_times(const std::vector<double>& outputs, double tau, std::initializer_list<double> events) {
  std::vector<double> stops;
  stops.reserve(2 * outputs.size() + 3);
  stops.push_back(0.0);
  const double last = outputs.empty() ? 0.0 : outputs.back();
  for (double e : events)
    if (e > 0.0 && e < last) stops.push_back(e);
  for (double t : outputs) {
    stops.push_back(t);
    if (t - tau >= -1e-9) stops.push_back(std::max(0.0, t - tau));
  }
  std::sort(stops.begin(), stops.end());
  std::vector<double> unique;
  unique.reserve(stops.size());
  for (double t : stops)
    if (unique.empty() || t - unique.back() > 1e-9) unique.push_back(t);
  return unique;
}

std::size_t find_stop(const std::vector<double>& stops, double t) {
  const auto it = std::lower_bound(stops.begin(), stops.end(), t - 1e-9);
  INSMC_ASSERT(it != stops.end() && std::abs(*it - t) <= 1e-9, "stop {} missing", t);
  return static_cast<std::size_t>(it - stops.begin());
}

/// The terms faster than the step, by their exact integrals over [t, t1]
/// (split): the random accelerometer processes add to the velocity
/// increments; the random platform rotations (drift process, angle random
/// walk) turn the measured force by −θ(s) × f^a within the step (first order
/// in θ, a few µrad per step), the drift process also turning the platform
/// for the steps that follow. (cm, sm): cos, sin ω_ie at the step's middle.
void add_process_terms(State& y, const Dynamics& d, const Perturbations& p, double t, double t1, double cm,
                       double sm) {
  const bool has_bias_process = !p.bias_process.empty(), has_vrw = !p.velocity_walk.empty();
  const bool has_drift_process = !p.drift_process.empty(), has_angle_walk = !p.angle_walk.empty();
  const bool turns = has_drift_process || has_angle_walk;
  if (has_bias_process || has_vrw || turns) {
    Vec3 dv = Vec3::Zero(), dw = Vec3::Zero();
    if (has_bias_process) {
      const GridProcess::Integrals b = p.bias_process.integrals(t, t1);
      dv += b.first;
      dw += b.second;
    }
    if (has_vrw) {
      const Vec3 v0 = p.velocity_walk.at(t);
      dv += p.velocity_walk.at(t1) - v0;
      dw += p.velocity_walk.integrals(t, t1).first - (t1 - t) * v0;
    }
    if (turns) {
      const Vec3 f_a = d.scale.asDiagonal() * (quaternion_matrix(y.segment<4>(kQ)).transpose() *
                                               rotate_z(cm, sm, d.site_specific_force_e));
      if (has_drift_process) {
        const GridProcess::Integrals w_int = p.drift_process.integrals(t, t1);
        dv -= w_int.second.cross(f_a);
        dw -= w_int.third.cross(f_a);
        turn_platform(y, w_int.first);
      }
      if (has_angle_walk) {
        const GridProcess::Integrals a_int = p.angle_walk.integrals(t, t1);
        dv -= a_int.first.cross(f_a);
        dw -= a_int.second.cross(f_a);
      }
    }
    y.segment<3>(kDV) += dv;
    y.segment<3>(kDW) += dw;
    y.segment<3>(kDVel) += d.c_hat * dv;
    y.segment<3>(kDR) += d.c_hat * dw;
  }
}

/// The sway motion in the platform over [t, t1], exactly: its inertial
/// displacement x(t) = R(t) C_n^e s(t) and velocity v(t) = R(t) C_n^e (ṡ + Ω × s)
/// give ΔV = v(t1) − v(t0), ΔW = x(t1) − x(t0) − h v(t0). The computer follows
/// the true motion, so δr keeps only the initial offsets.
void add_sway(State& y, const Dynamics& d, const Perturbations& p, double t, double t1, double tm, double w_ie,
              const Mat3& c_e_n, const Vec3& earth_axis_n) {
  const auto inertial = [&](double time, SwayState* velocity) {
    const SwayState st = sway_at(p.sway, time);
    const Mat3 r = earth_rotation(w_ie * time) * c_e_n;
    velocity->velocity_n = r * (st.velocity_n + earth_axis_n.cross(st.position_n));
    velocity->position_n = r * st.position_n;
  };
  SwayState a, b;  // here in i
  inertial(t, &a);
  inertial(t1, &b);
  Mat3 c_a_i = quaternion_matrix(y.segment<4>(kQ)).transpose();
  if (!p.angle_walk.empty()) c_a_i = rotation(p.angle_walk.at(tm)).transpose() * c_a_i;
  const Mat3 to_platform = d.scale.asDiagonal() * c_a_i;
  y.segment<3>(kDV) += to_platform * (b.velocity_n - a.velocity_n);
  y.segment<3>(kDW) += to_platform * (b.position_n - a.position_n - (t1 - t) * a.velocity_n);
}

/// The misalignment C' at switch-over (2.18a) and what the alignment
/// electronics saw: the loops' mean torquer commands (5.14) and
/// accelerometer outputs (5.19).
struct Switchover {
  Vec3 misalignment_rad, command_radps, accel_output_mps2;
};

Switchover switch_over(const TruthOptions& o, const ModelOptions& site_options, const UncertaintyVector& x_align,
                       const Perturbations& p) {
  Switchover out;
  if (o.alignment_loops) {
    // The loops in the time domain (2.9)/(2.13), the sway as (u)r̈ (t ≤ 0).
    std::function<Vec3(double)> sway_acceleration;
    if (!p.sway.empty())
      sway_acceleration = [&p](double t) {
        Vec3 a = Vec3::Zero();
        for (const SwayComponent& c : p.sway) {
          const double w = 2.0 * std::numbers::pi / c.period_s;
          a -= w * w * std::sin(w * t + c.phase_rad) * c.amplitude_n_m;
        }
        return a;
      };
    const AlignmentLoopRun loops =
        simulate_alignment_loops(o.system, site_options, *o.alignment_loops, x_align, sway_acceleration);
    out.misalignment_rad = loops.misalignment_rad + x_align.segment<3>(uncertainty_slot::kMisalignAlign) + p.misalignment_step_rad;  // (2.18a)
    out.command_radps = loops.mean_command_radps;
    out.accel_output_mps2 = loops.mean_accel_output_mps2;
  } else {
    // The loops in steady state (2.10)/(2.14); their commands (5.14) and
    // accelerometer outputs (5.19) as the alignment electronics see them.
    const Sensitivity3 steady = full_steady_state_misalignment(o.system, site_options);
    out.misalignment_rad = full_switchover_misalignment(o.system, site_options) * x_align + p.misalignment_step_rad;  // (2.18a)
    out.command_radps = torquer_commands(steady, site_options) * x_align;
    out.accel_output_mps2 = alignment_accelerometer_outputs(steady, site_options) * x_align;
  }
  return out;
}

/// The run's state at each stop of the integration.
struct StopRecords {
  std::vector<Vec3> velocity, error;
  std::vector<PulseCount3> pulses;
};

/// The records at the output times: the position error at each, and the
/// filtered accelerometer output error over the window τ before it against
/// the computer's f̂ of (4.1) with ĝ = `g_hat` (NaN before the first window).
TruthRun outputs_at(const std::vector<double>& output_times_s, const std::vector<double>& stops,
                    const StopRecords& at_stops, double g_hat, const Mat3& c_i_ap_hat, double w_ie, double L0,
                    double tau) {
  const double cosL = std::cos(L0);
  TruthRun run;
  const std::size_t n = output_times_s.size();
  run.t_s = output_times_s;
  run.position_error_ap_m.resize(n);
  run.accel_error_ap_mps2.resize(n);
  run.pulse_counts.resize(n);
  // (4.1): f̂^{a'} = Ĉ_i^{a'} C_n^i(t) (0, 0, −ĝ), C_n^i(t) e_z = −(cL cos ω_ie t, cL sin ω_ie t, sL).
  const double sinL = std::sin(L0);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (std::size_t k = 0; k < n; ++k) {
    const double tk = output_times_s[k];
    const std::size_t end = find_stop(stops, tk);
    run.position_error_ap_m[k] = at_stops.error[end];
    if (tk < tau - 1e-9) {
      run.accel_error_ap_mps2[k] = Vec3::Constant(nan);
      run.pulse_counts[k] = PulseCount3::Zero();
      continue;
    }
    const std::size_t begin = find_stop(stops, std::max(0.0, tk - tau));
    const double ta = stops[begin], tb = stops[end], span = tb - ta;
    const Vec3 mean_up(cosL * (std::sin(w_ie * tb) - std::sin(w_ie * ta)) / (w_ie * span),
                       cosL * (std::cos(w_ie * ta) - std::cos(w_ie * tb)) / (w_ie * span), sinL);
    const Vec3 f_hat = g_hat * (c_i_ap_hat * mean_up);
    run.accel_error_ap_mps2[k] = (at_stops.velocity[end] - at_stops.velocity[begin]) / span - f_hat;
    run.pulse_counts[k] = at_stops.pulses[end] - at_stops.pulses[begin];
  }
  return run;
}

/// The instruments of the run: mass unbalance, drift, scale factor, the
/// navigation bias (3.18) and the effects' terms on them (3.10)–(3.13).
void set_instruments(Dynamics& d, const UncertaintyVector& x, const Perturbations& p, const TruthOptions& o, double g_s,
                     double L0) {
  const double cosL = std::cos(L0);
  for (int k = 0; k < 3; ++k) {
    // (3.10) with MUX = 0: (3.13a) gives ω_MU = g MUZ cos² L0; the g·MUY drift
    // angle is g·MUY cos L0 (1 − cos ω_ie t)/ω_ie (errata.md#3-13).
    d.mass_unbalance(k, 1) = x[uncertainty_slot::kGyroMuyDrift + k] / g_s;
    const double w_mu = x[uncertainty_slot::kGyroMuDrift + k];
    if (w_mu != 0.0) {
      INSMC_ASSERT(cosL * cosL > 1e-12, "ω_MU needs cos L0 != 0 (L0 = {} rad)", L0);
      d.mass_unbalance(k, 2) = w_mu / (g_s * cosL * cosL);
    }
  }
  // ω_AI = ω_do − MU f_level, f_level = (0, 0, −g_s) (3.11), (3.12).
  d.drift_ai = x.segment<3>(uncertainty_slot::kGyroDrift) + g_s * d.mass_unbalance.col(2);
  d.scale = Vec3::Ones() + x.segment<3>(uncertainty_slot::kAccelScale);
  d.nav_bias = x.segment<3>(uncertainty_slot::kAccelBias) + p.nav_bias_step_mps2;
  for (int k = 0; k < 2; ++k)
    d.nav_bias[k] += x[uncertainty_slot::kBiasChangeConst + k] + x[uncertainty_slot::kBiasChangeAlign + k];  // (3.18)
  d.quadratic = p.accel_quadratic_per_mps2;
  d.anisoelastic = p.anisoelastic_radps_per_mps2sq;
  d.bias_transients = &p.bias_transients;
  d.drift_transients = &p.drift_transients;
  d.torquer = &o.torquer_command_radps;
  d.compensation = &o.accel_compensation;
}

/// Points 5, 6 at time t: the computer's integrators get the position and
/// velocity of (3.22), (3.23) for its stationary vehicle (r_c0 at switch-over),
/// turned with the earth to now, plus the resets' own errors; the true
/// vehicle keeps its motion (sway).
void reset_computer(State& y, const Dynamics& d, const Perturbations& p, const UncertaintyVector& x, double t,
                    double w_ie, const Vec3& r_c0, const Mat3& c_e_n, const Mat3& c_ap_i) {
  const Vec3 earth_axis(0.0, 0.0, w_ie);
  const Vec3 earth_axis_n = c_e_n.transpose() * earth_axis;
  const Mat3 turn = earth_rotation(w_ie * t);
  const Vec3 offset_i = turn * (r_c0 - d.site_position_e);
  const SwayState st = sway_at(p.sway, t);
  const Mat3 to_i = turn * c_e_n;
  y.segment<3>(kDR) = offset_i - to_i * st.position_n;
  y.segment<3>(kDVel) = earth_axis.cross(offset_i) - to_i * (st.velocity_n + earth_axis_n.cross(st.position_n));
  // The resets' own errors (catalogue: reset_position_error, reset_velocity_error), given in a'.
  y.segment<3>(kDR) += c_ap_i * x.segment<3>(uncertainty_slot::kResetPositionError);
  y.segment<3>(kDVel) += c_ap_i * x.segment<3>(uncertainty_slot::kResetVelocityError);
}

/// The gravity fields of the computer and of the truth, and the run's
/// effects realized (their draws made here, once) at the site's gravity.
struct RunEffects {
  GravityField computer_field, true_field;
  Perturbations p;
};

RunEffects realize_run_effects(const TruthOptions& o, double duration_s, const NormalSource& noise) {
  const ModelOptions& m = o.model;
  const double w_ie = m.earth_rate_radps, r0 = m.radius_m, L0 = m.latitude_rad;
  const double j2_computer = o.j2_gravity ? kEarthJ2 : 0.0;
  const GravityField computer_field = model_gravity_field(m.gravity_mps2, r0, j2_computer);
  GravityField true_field = computer_field;
  // Site gravity before the effects (for their normalizations); the J2 effect
  // changes it by ~1e-3, which no effect's size depends on.
  const Vec3 probe = position_for_plumb_latitude(true_field, w_ie, r0, L0);
  EffectContext context;
  context.duration_s = duration_s;
  context.noise_grid_s = o.noise_grid_s;
  context.site_gravity_mps2 =
      (true_field.gravitation(probe) + w_ie * w_ie * Vec3(probe.x(), probe.y(), 0.0)).norm();
  context.latitude_rad = L0;
  context.earth_rate_radps = w_ie;
  context.noise = noise ? &noise : nullptr;
  RunEffects out{computer_field, true_field, realize_effects(o.effects, context)};
  out.true_field.j2 += out.p.extra_j2;
  return out;
}

}  // namespace

Mat3 switchover_attitude(const Vec3& c_prime, const Vec3& f_ap) {
  const double g = f_ap.norm();
  const Vec3 target_h = f_ap - c_prime.cross(f_ap);
  Vec3 f_a(target_h.x(), target_h.y(), 0.0);
  f_a.z() = -std::sqrt(g * g - f_a.x() * f_a.x() - f_a.y() * f_a.y());
  const Mat3 azimuth = Eigen::AngleAxisd(c_prime.z(), Vec3::UnitZ()).toRotationMatrix();
  const Vec3 f_a1 = azimuth.transpose() * f_ap;
  return azimuth * minimal_rotation(f_a / g, f_a1 / g);
}

namespace {

/// What a latitude beyond it is told.
std::string truth_latitude_limit_text() {
  return fmt::format("the truth simulator needs |latitude| <= {} deg (nearer a pole it leaves the linear level: "
                     "docs/truth-vs-models.md)",
                     kMaxTruthLatitudeDeg);
}

}  // namespace

std::optional<InputError> truth_latitude_error(double latitude_rad, std::string field) {
  if (std::abs(latitude_rad) <= kMaxTruthLatitudeDeg * kDegToRad) return std::nullopt;
  return InputError(std::move(field), fmt::format("{}deg", latitude_rad / kDegToRad), truth_latitude_limit_text());
}

void validate(const TruthOptions& o) {
  const auto bad = [](std::string field, double v, std::string allowed) {
    return InputError(std::move(field), fmt::format("{}", v), std::move(allowed));
  };
  // Within a degree of a pole the truth level leaves the linear level:
  // measured (uncompensated, system 1, 84 min) 0.2 % apart at 89°, 0.5 % at
  // 89.5°, 15 % at 89.9°, diverging at 89.99° (docs/truth-vs-models.md).
  if (auto err = truth_latitude_error(o.model.latitude_rad, "latitude")) throw *err;
  // Pulse weights up to 10 m/s, filter intervals from 1 ms and steps from
  // 10 ms: the output and step counts of a 48 h run stay bounded.
  if (!(o.dv_pulse_mps >= 0 && o.dv_pulse_mps <= magnitude_limit(Dimension::kVelocity)))
    throw bad("dv_pulse_mps", o.dv_pulse_mps, "must lie in [0, 10] m/s (0 = continuous)");
  if (!(o.filter_interval_s >= 1e-3 && o.filter_interval_s <= magnitude_limit(Dimension::kTime)))
    throw bad("filter_interval_s", o.filter_interval_s, "must lie in [0.001, 172800] s");
  if (!(o.step_s >= 0.01 && o.step_s <= 60)) throw bad("step_s", o.step_s, "must lie in [0.01, 60] s");
  if (!(o.noise_grid_s > 0) || !std::isfinite(o.noise_grid_s))
    throw bad("noise_grid_s", o.noise_grid_s, "must be > 0");
  if (!std::isfinite(o.reset_at_s)) throw bad("reset_at_s", o.reset_at_s, "must be finite (negative = no reset)");
  const AccelCompensation& c = o.accel_compensation;
  if (!(c.start_s >= 0) || !std::isfinite(c.start_s) || !c.step_mps2.allFinite() || !c.ramp_mps3.allFinite())
    throw bad("accel_compensation.start_s", c.start_s, "must be >= 0 with a finite step and ramp");
  for (int k = 0; k < 3; ++k)
    if (!(o.pulse_phase[k] >= -0.5 && o.pulse_phase[k] < 0.5))
      throw bad(fmt::format("pulse_phase[{}]", k), o.pulse_phase[k], "must be in [-0.5, 0.5)");
  if (o.alignment_loops) validate(*o.alignment_loops);
  for (const EffectSpec& e : o.effects) validate_effect(e);
}

std::vector<double> uniform_times(double end_s, double interval_s, bool include_zero) {
  INSMC_ASSERT(interval_s > 0 && end_s >= 0, "end {} interval {}", end_s, interval_s);
  std::vector<double> t;
  if (include_zero) t.push_back(0.0);
  for (long k = 1;; ++k) {
    const double tk = static_cast<double>(k) * interval_s;
    if (tk > end_s + kLatticeTolS) break;
    t.push_back(std::abs(tk - end_s) <= kLatticeTolS ? end_s : tk);
  }
  if (t.empty() || t.back() < end_s) t.push_back(end_s);
  return t;
}

namespace {

/// The callers' options are checked at the edge (validate()): a failure
/// here is a bug, not an input error.
void assert_valid(const TruthOptions& o, const std::vector<double>& output_times_s) {
  try {
    validate(o);
  } catch (const InputError& e) {
    INSMC_ASSERT(false, "invalid TruthOptions: {}", e.what());
  }
  for (std::size_t k = 0; k < output_times_s.size(); ++k)
    INSMC_ASSERT(output_times_s[k] >= 0 && (k == 0 || output_times_s[k] >= output_times_s[k - 1]),
                 "output times must ascend from 0: {} at {}", output_times_s[k], k);
}

}  // namespace

TruthRun simulate_truth(const TruthOptions& o, const UncertaintyVector& x,
                        const std::vector<double>& output_times_s, const NormalSource& noise) {
  assert_valid(o, output_times_s);
  const ModelOptions& m = o.model;
  const double w_ie = m.earth_rate_radps, r0 = m.radius_m, L0 = m.latitude_rad;
  const double tau = o.filter_interval_s;
  const AccelCompensation& compensation = o.accel_compensation;
  const std::vector<double> stops =
      stop_times(output_times_s, tau, {compensation.active() ? compensation.start_s : -1.0, o.reset_at_s});

  // ---- effects ---------------------------------------------------------------
  const RunEffects effects = realize_run_effects(o, stops.back(), noise);
  const GravityField& computer_field = effects.computer_field;
  const GravityField& true_field = effects.true_field;
  const Perturbations& p = effects.p;

  // ---- the site (truth) ------------------------------------------------------
  Dynamics d;
  d.site_position_e = position_for_plumb_latitude(true_field, w_ie, r0, L0);
  const Vec3 reference_gravitation = true_field.gravitation(d.site_position_e);
  const Vec3 centripetal = -w_ie * w_ie * Vec3(d.site_position_e.x(), d.site_position_e.y(), 0.0);
  const double g_s = (reference_gravitation - centripetal).norm();
  // Deflection of the vertical: true gravity (0, 0, g) + α^n, α^n = (ξ g, −η g, 0) (2.8b).
  const double xi = x[uncertainty_slot::kDeflection + 0] + p.deflection_rad[0];
  const double eta = x[uncertainty_slot::kDeflection + 1] + p.deflection_rad[1];
  const Mat3 c_e_n = C_i_n(L0, 0.0);
  d.site_gravitation_e = reference_gravitation + c_e_n * Vec3(xi * g_s, -eta * g_s, 0.0);
  d.site_specific_force_e = centripetal - d.site_gravitation_e;

  // ---- alignment: misalignment at switch-over ----------------------------------
  ModelOptions site_options = m;
  site_options.gravity_mps2 = g_s;  // the leveling loops null the measured force
  UncertaintyVector x_align = x;
  x_align.segment<3>(uncertainty_slot::kAccelBias) += p.alignment_bias_mps2;
  x_align.segment<3>(uncertainty_slot::kGyroDrift) += p.alignment_drift_radps;
  x_align.segment<2>(uncertainty_slot::kDeflection) += p.deflection_rad;
  const Switchover switchover = switch_over(o, site_options, x_align, p);
  const Vec3& c_prime = switchover.misalignment_rad;
  const Mat3 c_i_ap = C_ap_i(L0);
  const Mat3 c_ap_i = c_i_ap.transpose();
  // C_{a'}^{a0} = I + ψ, ψ = paper_skew(C') = −[C'×] (2.17), (2.18): to first
  // order C_a^{a'} = I + [C'×].
  const Vec3 f_ap0 = c_i_ap * d.site_specific_force_e;
  const Eigen::Vector4d q0 = matrix_quaternion(c_ap_i * switchover_attitude(c_prime, f_ap0));

  // ---- instruments -------------------------------------------------------------
  set_instruments(d, x, p, o, g_s, L0);

  // ---- navigation computer -----------------------------------------------------
  const double latitude_hat = L0 + x[uncertainty_slot::kLatitudeError];
  const Mat3 c_i_ap_hat = C_ap_i(latitude_hat);
  d.c_hat = c_i_ap_hat.transpose();  // (3.20)
  d.computer_field = computer_field;
  d.computer_radius = r0 + x[uncertainty_slot::kAltitudeError];
  d.computer_mu_over_r3 = computer_field.mu_m3ps2 / std::pow(d.computer_radius, 3);
  // (3.22)–(3.23): position from L̂0 and the external altitude with the
  // computer's own field; velocity of that point on the turning earth.
  const Vec3 earth_axis(0.0, 0.0, w_ie);
  const Vec3 r_c0 = position_for_plumb_latitude(computer_field, w_ie, d.computer_radius, latitude_hat);
  const Vec3 v_c0 = earth_axis.cross(r_c0) + c_ap_i * x.segment<3>(uncertainty_slot::kInitialVelocity);
  const SwayState sway0 = sway_at(p.sway, 0.0);
  const Vec3 earth_axis_n = c_e_n.transpose() * earth_axis;  // Ω in the site's n frame
  const Vec3 sway_r0 = c_e_n * sway0.position_n;
  const Vec3 sway_v0 = c_e_n * (sway0.velocity_n + earth_axis_n.cross(sway0.position_n));

  State y = State::Zero();
  y.segment<4>(kQ) = q0;
  y.segment<3>(kDR) = r_c0 - d.site_position_e - sway_r0;
  y.segment<3>(kDVel) = v_c0 - earth_axis.cross(d.site_position_e) - sway_v0;

  // ---- pulses ------------------------------------------------------------------
  const double w = p.dv_pulse_mps.value_or(o.dv_pulse_mps);
  Vec3 rho0 = w * o.pulse_phase;  // the remainder the computer's count starts from
  Vec3 rho = rho0;               // accumulator remainder
  Vec3 remainder_integral = Vec3::Zero();  // P = ∫ (ρ − ρ0) dt
  PulseCount3 pulses = PulseCount3::Zero();
  Vec3 velocity_sum = Vec3::Zero();  // ∫ f_m (continuous)

  // ---- records at the stops ------------------------------------------------------
  StopRecords at_stops{std::vector<Vec3>(stops.size()), std::vector<Vec3>(stops.size()),
                       std::vector<PulseCount3>(stops.size())};
  const auto record = [&](std::size_t k) {
    at_stops.velocity[k] = w > 0 ? Vec3(w * pulses.cast<double>()) : velocity_sum;
    at_stops.pulses[k] = pulses;
    at_stops.error[k] = c_i_ap * (y.segment<3>(kDR) - d.c_hat * remainder_integral);
  };
  record(0);

  const bool has_sway = !p.sway.empty();
  double t = 0.0, c0 = 1.0, s0 = 0.0;
  State k1, k2, k3, k4;
  for (std::size_t stop = 1; stop < stops.size(); ++stop) {
    const double span = stops[stop] - t;
    const int steps = std::max(1, static_cast<int>(std::ceil(span / o.step_s - 1e-9)));
    const double h = span / steps;
    for (int i = 0; i < steps; ++i) {
      const double tm = t + 0.5 * h, t1 = (i + 1 == steps) ? stops[stop] : t + h;
      const double cm = std::cos(w_ie * tm), sm = std::sin(w_ie * tm);
      const double c1 = std::cos(w_ie * t1), s1 = std::sin(w_ie * t1);
      d.quantization_offset_i = d.c_hat * remainder_integral;
      d.compensating = compensation.active() && t >= compensation.start_s - 1e-9;
      y.segment<6>(kDV).setZero();
      d.derivative(t, c0, s0, y, k1);
      d.derivative(tm, cm, sm, y + 0.5 * h * k1, k2);
      d.derivative(tm, cm, sm, y + 0.5 * h * k2, k3);
      d.derivative(t1, c1, s1, y + h * k3, k4);
      y += h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
      y.segment<4>(kQ).normalize();
      add_process_terms(y, d, p, t, t1, cm, sm);
      if (has_sway) add_sway(y, d, p, t, t1, tm, w_ie, c_e_n, earth_axis_n);
      // Pulses: accumulator a(s) = ρ + ΔV(s); the computer's velocity lags the
      // continuous one by Ĉ(ρ − ρ0), its position by Ĉ ∫(ρ − ρ0) dt.
      const Vec3 dv_step = y.segment<3>(kDV), dw_step = y.segment<3>(kDW);
      velocity_sum += dv_step;
      if (w > 0) {
        for (int k = 0; k < 3; ++k) {
          const double a1 = rho[k] + dv_step[k];
          const double n = std::floor(a1 / w + 0.5);
          const double integral = integral_of_remainder(rho[k], dv_step[k], dw_step[k], t1 - t, w);
          remainder_integral[k] += integral - (t1 - t) * rho0[k];
          pulses[k] += static_cast<std::int64_t>(n);
          rho[k] = a1 - n * w;
        }
      }
      t = t1;
      c0 = c1;
      s0 = s1;
    }
    record(stop);
    if (o.reset_at_s >= 0.0 && std::abs(stops[stop] - o.reset_at_s) <= 1e-9) {
      // Points 5, 6; the pulse count restarts from the present remainder.
      reset_computer(y, d, p, x, t, w_ie, r_c0, c_e_n, c_ap_i);
      rho0 = rho;
      remainder_integral.setZero();
      record(stop);
    }
  }

  TruthRun run = outputs_at(output_times_s, stops, at_stops, g_s * (1.0 - 3.0 * x[uncertainty_slot::kAltitudeError] / r0),
                            c_i_ap_hat, w_ie, L0, tau);
  run.dv_pulse_mps = w;
  run.site_gravity_mps2 = g_s;
  run.switchover_misalignment_rad = c_prime;
  run.alignment_command_radps = switchover.command_radps;
  run.alignment_accel_output_mps2 = switchover.accel_output_mps2;
  return run;
}

}  // namespace insmc
