#include "montecarlo/study/bench/truth_reference.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "lib/alignment/alignment.h"
#include "lib/common/assert.h"
#include "lib/truth/earth_model.h"
#include "lib/truth/simulator.h"  // switchover_attitude: the initial platform attitude

namespace insmc::mc {
namespace {

/// What RK4 integrates. dv, dw restart at zero each step: the velocity and
/// its integral accumulated by the accelerometers over the step (platform
/// frame), which the pulse counters then count.
struct State {
  Eigen::Vector4d q;  // C_a^i as (w, x, y, z)
  Vec3 dv, dw;        // [m/s], [m]
  Vec3 dr, dvel;      // δr = r_c − r [m], δv [m/s], i frame
};

State plus(const State& y, double h, const State& k) {
  return {y.q + h * k.q, y.dv + h * k.dv, y.dw + h * k.dw, y.dr + h * k.dr, y.dvel + h * k.dvel};
}

/// The sample's constants of the right-hand side.
struct Sample {
  Vec3 site_position_e, site_gravitation_e, site_force_e;  // truth, e frame (= i at t = 0)
  Vec3 scale, bias;                  // f_m = scale ∘ f^a + bias (3.14)–(3.18)
  Vec3 drift, mu_y, mu_z;            // ω = drift + MU f^a, MU = [0 mu_y mu_z] (MUX = 0)
  Mat3 c_hat;                        // Ĉ_a^i of the computer (3.20)
  double mu_over_r3 = 0.0;           // μ/(r0 + δh)³ of the computer's gravitation
  Vec3 offset_i = Vec3::Zero();      // Ĉ ∫(ρ − ρ0): the computer's position lag, held over a step
};

/// R_z(ω_ie t) v with (c, s) its cosine and sine: e → i.
Vec3 rz(double c, double s, const Vec3& v) { return Vec3(c * v.x() - s * v.y(), s * v.x() + c * v.y(), v.z()); }

void rates(const Sample& p, double c, double s, const State& y, State& k) {
  const double qw = y.q[0], qx = y.q[1], qy = y.q[2], qz = y.q[3];
  Mat3 c_a_i;
  c_a_i << 1 - 2 * (qy * qy + qz * qz), 2 * (qx * qy - qw * qz), 2 * (qx * qz + qw * qy),  //
      2 * (qx * qy + qw * qz), 1 - 2 * (qx * qx + qz * qz), 2 * (qy * qz - qw * qx),        //
      2 * (qx * qz - qw * qy), 2 * (qy * qz + qw * qx), 1 - 2 * (qx * qx + qy * qy);
  const Vec3 f_i = rz(c, s, p.site_force_e);
  const Vec3 f_a = c_a_i.transpose() * f_i;
  const Vec3 f_m = p.scale.cwiseProduct(f_a) + p.bias;
  const Vec3 omega = p.drift + p.mu_y * f_a.y() + p.mu_z * f_a.z();
  const Vec3 qv(qx, qy, qz);
  k.q[0] = -0.5 * qv.dot(omega);  // q̇ = ½ q ⊗ (0, ω)
  k.q.tail<3>() = 0.5 * (qw * omega + qv.cross(omega));
  k.dv = f_m;
  k.dw = y.dv;
  // δv̇ = G_c(r_c) − G(r) + Ĉ f_m − f^i (spherical computer gravitation).
  const Vec3 r_c = rz(c, s, p.site_position_e) + y.dr - p.offset_i;
  k.dvel = -p.mu_over_r3 * r_c - rz(c, s, p.site_gravitation_e) + p.c_hat * f_m - f_i;
  k.dr = y.dvel;
}

/// ρ(a) = a − w round(a/w), the rounding quantizer's remainder.
double remainder_of(double a, double w) { return a - w * std::floor(a / w + 0.5); }

/// ∫_0^h ρ(a0 + ΔV(s)) ds with ΔV(s) = α s + β s² matching ΔV(h) = dv and
/// ∫ΔV = dw: ∫a − w ∫round(a/w), the second from the crossing times when at
/// most 24 pulses fall in the step, else (dense pulses) ∫ρ along the
/// straight path from a0 to a0 + dv. The simulator's pulse model, thresholds
/// included, so that both make the same discrete choices.
double remainder_integral(double a0, double dv, double dw, double h, double w) {
  const auto level = [w](double a) { return std::floor(a / w + 0.5); };
  const double beta = (3.0 * dv * h - 6.0 * dw) / (h * h * h), alpha = dv / h - beta * h;
  const auto a_at = [&](double s) { return a0 + (alpha + beta * s) * s; };
  double ends[3] = {0.0, h, h};  // monotone pieces of the path
  int pieces = 1;
  if (beta != 0.0 && -alpha / (2.0 * beta) > 0.0 && -alpha / (2.0 * beta) < h) {
    ends[1] = -alpha / (2.0 * beta);
    pieces = 2;
  }
  double crossings = 0.0;
  for (int i = 0; i < pieces; ++i) crossings += std::abs(level(a_at(ends[i + 1])) - level(a_at(ends[i])));
  if (crossings > 24) {
    const double a1 = a0 + dv;
    if (std::abs(dv) < 1e-9 * w) return h * remainder_of(0.5 * (a0 + a1), w);
    const double r0 = remainder_of(a0, w), r1 = remainder_of(a1, w);
    return h * 0.5 * (r1 * r1 - r0 * r0) / dv;
  }
  double integral_q = 0.0;  // ∫ round(a/w) ds
  for (int i = 0; i < pieces; ++i) {
    const double sa = ends[i], sb = ends[i + 1], qa = level(a_at(sa)), qb = level(a_at(sb));
    const double dir = qb > qa ? 1.0 : -1.0;
    integral_q += qa * (sb - sa);
    for (double q = qa; q != qb; q += dir) {  // each crossing adds dir from its time on
      const double c = a0 - (q + 0.5 * dir) * w;  // β s² + α s + c = 0
      double root;
      if (std::abs(beta) * h < 1e-12 * std::abs(alpha)) {
        root = -c / alpha;
      } else {
        const double sq = std::sqrt(std::max(0.0, alpha * alpha - 4.0 * beta * c));
        const double m = -0.5 * (alpha + (alpha >= 0 ? sq : -sq));
        const double r1 = m / beta, r2 = m != 0.0 ? c / m : r1;
        root = (r1 >= sa - 1e-9 * h && r1 <= sb + 1e-9 * h) ? r1 : r2;
      }
      integral_q += dir * (sb - std::clamp(root, sa, sb));
    }
  }
  return h * a0 + dw - w * integral_q;
}

}  // namespace

TruthReference::TruthReference(const ModelOptions& model, System system, double dv_pulse_mps,
                               double filter_interval_s, std::vector<double> output_times_s, double step_s)
    : model_(model), dv_pulse_mps_(dv_pulse_mps), step_s_(step_s) {
  INSMC_ASSERT(step_s > 0 && filter_interval_s > 0 && dv_pulse_mps >= 0, "step {} s, τ {} s, pulse {} m/s",
               step_s, filter_interval_s, dv_pulse_mps);
  std::vector<double> stops{0.0};
  for (double t : output_times_s) {
    stops.push_back(t);
    if (t - filter_interval_s >= -1e-9) stops.push_back(std::max(0.0, t - filter_interval_s));
  }
  std::sort(stops.begin(), stops.end());
  for (double t : stops)
    if (stops_s_.empty() || t - stops_s_.back() > 1e-9) stops_s_.push_back(t);
  for (double t : output_times_s)
    output_stop_.push_back(
        static_cast<std::size_t>(std::lower_bound(stops_s_.begin(), stops_s_.end(), t - 1e-9) - stops_s_.begin()));

  const double w = model.earth_rate_radps;
  const GravityField field = model_gravity_field(model.gravity_mps2, model.radius_m, 0.0);
  site_position_e_m_ = position_for_plumb_latitude(field, w, model.radius_m, model.latitude_rad);
  reference_gravitation_e_mps2_ = field.gravitation(site_position_e_m_);
  centripetal_e_mps2_ = -w * w * Vec3(site_position_e_m_.x(), site_position_e_m_.y(), 0.0);
  site_gravity_mps2_ = (reference_gravitation_e_mps2_ - centripetal_e_mps2_).norm();
  ModelOptions site = model;
  site.gravity_mps2 = site_gravity_mps2_;  // the leveling loops null the measured force
  misalignment_map_ = full_switchover_misalignment(system, site);
  c_e_n_ = C_i_n(model.latitude_rad, 0.0);
  c_i_ap_ = C_ap_i(model.latitude_rad);
}

void TruthReference::run(const UncertaintyVector& x, const Vec3& pulse_phase, Vec3* position_error_ap_m) const {
  const double w_ie = model_.earth_rate_radps, g_s = site_gravity_mps2_, cos_l = std::cos(model_.latitude_rad);
  Sample p;
  p.site_position_e = site_position_e_m_;
  // Deflection of the vertical ξ, η as a gravity anomaly (2.8b).
  p.site_gravitation_e = reference_gravitation_e_mps2_ +
                         c_e_n_ * Vec3(x[uncertainty_slot::kDeflection] * g_s, -x[uncertainty_slot::kDeflection + 1] * g_s, 0.0);
  p.site_force_e = centripetal_e_mps2_ - p.site_gravitation_e;
  for (int k = 0; k < 3; ++k) {
    p.mu_y[k] = x[uncertainty_slot::kGyroMuyDrift + k] / g_s;
    p.mu_z[k] = x[uncertainty_slot::kGyroMuDrift + k] / (g_s * cos_l * cos_l);
  }
  p.drift = x.segment<3>(uncertainty_slot::kGyroDrift) + g_s * p.mu_z;  // ω_AI = ω_do − MU f_level
  p.scale = Vec3::Ones() + x.segment<3>(uncertainty_slot::kAccelScale);
  p.bias = x.segment<3>(uncertainty_slot::kAccelBias);
  for (int k = 0; k < 2; ++k) p.bias[k] += x[uncertainty_slot::kBiasChangeConst + k] + x[uncertainty_slot::kBiasChangeAlign + k];
  const double latitude_hat = model_.latitude_rad + x[uncertainty_slot::kLatitudeError];
  const double radius_m = model_.radius_m + x[uncertainty_slot::kAltitudeError];
  const GravityField field = model_gravity_field(model_.gravity_mps2, model_.radius_m, 0.0);
  p.c_hat = C_ap_i(latitude_hat).transpose();
  p.mu_over_r3 = field.mu_m3ps2 / (radius_m * radius_m * radius_m);

  // Initial state: the platform as the alignment left it, the computer's
  // position from L̂0 and the external altitude, at rest on the earth (3.22)–(3.23).
  const Mat3 c_ap_i = c_i_ap_.transpose();
  const Eigen::Quaterniond q0(c_ap_i * switchover_attitude(misalignment_map_ * x, c_i_ap_ * p.site_force_e));
  const Vec3 omega_e(0.0, 0.0, w_ie);
  const Vec3 r_c0 = position_for_plumb_latitude(field, w_ie, radius_m, latitude_hat);
  State y{Eigen::Vector4d(q0.w(), q0.x(), q0.y(), q0.z()), Vec3::Zero(), Vec3::Zero(), r_c0 - p.site_position_e,
          omega_e.cross(r_c0) + c_ap_i * x.segment<3>(uncertainty_slot::kInitialVelocity) - omega_e.cross(p.site_position_e)};

  const double w = dv_pulse_mps_;
  const Vec3 rho0 = w * pulse_phase;
  Vec3 rho = rho0, lag = Vec3::Zero();  // accumulator remainder; ∫(ρ − ρ0) dt
  std::size_t next = 0;
  const auto record = [&](std::size_t stop) {
    for (; next < output_stop_.size() && output_stop_[next] == stop; ++next)
      position_error_ap_m[next] = c_i_ap_ * (y.dr - p.c_hat * lag);
  };
  record(0);
  double t = 0.0, c0 = 1.0, s0 = 0.0;
  State k1, k2, k3, k4;
  for (std::size_t stop = 1; stop < stops_s_.size(); ++stop) {
    const double span = stops_s_[stop] - t;
    const int steps = std::max(1, static_cast<int>(std::ceil(span / step_s_ - 1e-9)));
    const double h = span / steps;
    for (int i = 0; i < steps; ++i) {
      const double tm = t + 0.5 * h, t1 = i + 1 == steps ? stops_s_[stop] : t + h;
      const double cm = std::cos(w_ie * tm), sm = std::sin(w_ie * tm);
      const double c1 = std::cos(w_ie * t1), s1 = std::sin(w_ie * t1);
      p.offset_i = p.c_hat * lag;
      y.dv.setZero();
      y.dw.setZero();
      rates(p, c0, s0, y, k1);
      rates(p, cm, sm, plus(y, 0.5 * h, k1), k2);
      rates(p, cm, sm, plus(y, 0.5 * h, k2), k3);
      rates(p, c1, s1, plus(y, h, k3), k4);
      y.q += h / 6.0 * (k1.q + 2.0 * k2.q + 2.0 * k3.q + k4.q);
      y.q.normalize();
      y.dv += h / 6.0 * (k1.dv + 2.0 * k2.dv + 2.0 * k3.dv + k4.dv);
      y.dw += h / 6.0 * (k1.dw + 2.0 * k2.dw + 2.0 * k3.dw + k4.dw);
      y.dr += h / 6.0 * (k1.dr + 2.0 * k2.dr + 2.0 * k3.dr + k4.dr);
      y.dvel += h / 6.0 * (k1.dvel + 2.0 * k2.dvel + 2.0 * k3.dvel + k4.dvel);
      if (w > 0) {
        for (int k = 0; k < 3; ++k) {  // pulses: the computer lags by Ĉ(ρ − ρ0) in velocity
          lag[k] += remainder_integral(rho[k], y.dv[k], y.dw[k], t1 - t, w) - (t1 - t) * rho0[k];
          rho[k] = remainder_of(rho[k] + y.dv[k], w);
        }
      }
      t = t1, c0 = c1, s0 = s1;
    }
    record(stop);
  }
}

}  // namespace insmc::mc
