#include "montecarlo/gap/candidates/candidates.h"

#include <Eigen/Cholesky>
#include <cmath>
#include <numbers>

#include "lib/frames/frames.h"
#include "lib/units/units.h"
#include "montecarlo/gap/model/response.h"

namespace insmc::gap {
namespace {

constexpr double kUg = 1e-6 * kGravityMps2;  // µg in m/s²

std::vector<double> scaled(std::initializer_list<double> values, double unit) {
  std::vector<double> out;
  for (double v : values) out.push_back(v * unit);
  return out;
}

/// lo, lo·r, lo·r², … up to hi (within 1 %), r = 10^(1/4), × unit: the same
/// relative step (×1.78) for every scale parameter, so no candidate is
/// favoured by a grid that happens to hold the data's value.
std::vector<double> log_grid(double lo, double hi, double unit) {
  std::vector<double> out;
  for (int k = 0;; ++k) {
    const double v = lo * std::pow(10.0, k / 4.0);
    if (v > hi * 1.01) break;
    out.push_back(v * unit);
  }
  return out;
}

double layout_end(const Layout& layout) {
  double end = 0.0;
  for (const ObservationRow& r : layout.rows) end = std::max(end, r.t_s);
  return end;
}

/// Knots t_j = j Δ, j = 1..K, covering the run (the value at 0 is the
/// alignment's: processes enter as changes since switch-over).
std::vector<double> knots(const Layout& layout, double spacing_s) {
  std::vector<double> k;
  const double end = layout_end(layout);
  for (double t = spacing_s; t < end + spacing_s; t += spacing_s) k.push_back(t);
  return k;
}

/// Knot spacing for a process of correlation time tau (0: random walk): a
/// Gauss–Markov process is resolved by knots a correlation time apart (the
/// bridge modes below carry what lies between), within bounds that keep the
/// model small.
double knot_spacing(double tau) {
  return tau > 0 ? std::clamp(tau, kMinKnotSpacingS, kKnotSpacingS) : kMinKnotSpacingS;
}

/// Hat function of knot t_j (spacing d) and its integral from 0 to t.
double hat(double t, double tj, double d) { return std::max(0.0, 1.0 - std::abs(t - tj) / d); }
double hat_integral(double t, double tj, double d) {
  const double a = tj - d;
  if (t <= a) return 0.0;
  if (t <= tj) return (t - a) * (t - a) / (2 * d);
  if (t <= tj + d) return d / 2 + (t - tj) - (t - tj) * (t - tj) / (2 * d);
  return d;
}

/// Covariance of the change since 0 of a unit process at s and t:
/// random walk (tau 0, unit variance after 1 h) or Gauss–Markov (unit σ).
double change_covariance(double s, double t, double tau) {
  if (tau <= 0) return std::min(s, t) / 3600.0;
  return std::exp(-std::abs(s - t) / tau) - std::exp(-s / tau) - std::exp(-t / tau) + 1.0;
}

/// Diffusion of a unit process: a random walk's 1/(1 h); a Gauss–Markov
/// process is locally one with 2σ²/τ.
double unit_diffusion(double tau) { return tau > 0 ? 2.0 / tau : 1.0 / 3600.0; }

/// Between two knots a process is a bridge B (zero at both knots). Its
/// Karhunen–Loève modes on an interval of Δ are sin(mπu/Δ) with variances
/// 2qΔ/(mπ)²: the first carries 8/π⁴ ≈ 98.5 % of the variance of ∫B (an
/// impulse through (3.24) on every later r row) and is a column (kBridgeModes
/// of them per interval); the rest, qΔ(1/6 − Σ 1/(mπ)²) on average, is seen
/// by the f rows and enters them as noise. Checked against truth runs with
/// 150 s knots (tests/unit/montecarlo/gap/model): a velocity random walk, which r sees
/// through one integration only, is the most demanding.
constexpr int kBridgeModes = 1;
double bridge_rest_share(int modes) {
  double share = 1.0 / 6.0;
  for (int m = 1; m <= modes; ++m) share -= 1.0 / (m * m * std::numbers::pi * std::numbers::pi);
  return share;
}

enum class Drive { kAccel, kAngle, kRate, kVelocity };

/// Unit response of a process on the knots, per axis k: columns 3j + k (j <
/// K) the knot values, mixed by the Cholesky factor of their covariance, and
/// 3(K(m + 1) + j) + k bridge mode m (0-based) of interval j; every
/// coefficient is independent with variance σ².
Eigen::MatrixXd process_columns(const LayoutContext& ctx, Drive drive, double tau) {
  const std::string key = "process" + std::to_string(static_cast<int>(drive)) + ":" + std::to_string(tau);
  if (auto it = ctx.cache.find(key); it != ctx.cache.end()) return it->second;
  const Layout& layout = *ctx.layout;
  if (layout.nav == NavSegment::kRestart && layout.test_rows < static_cast<int>(layout.rows.size())) {
    // After a realignment the process is taken from the new switch-over,
    // independent of what the test run saw: columns of its own.
    const Layout test = layout.test_part(), nav = layout.restarted_part();
    const Eigen::MatrixXd a = process_columns({&test, ctx.site, ctx.base, {}}, drive, tau);
    const Eigen::MatrixXd b = process_columns({&nav, ctx.site, ctx.base, {}}, drive, tau);
    Eigen::MatrixXd out = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(layout.rows.size()), a.cols() + b.cols());
    out.topLeftCorner(a.rows(), a.cols()) = a;
    out.bottomRightCorner(b.rows(), b.cols()) = b;
    ctx.cache[key] = out;
    return out;
  }
  const double d = knot_spacing(tau);
  const std::vector<double> tk = knots(*ctx.layout, d);
  const int K = static_cast<int>(tk.size()), M = kBridgeModes;
  Eigen::MatrixXd cov(K, K);
  for (int i = 0; i < K; ++i)
    for (int j = 0; j < K; ++j) cov(i, j) = change_covariance(tk[i], tk[j], tau);
  cov.diagonal().array() += 1e-12 * cov.diagonal().maxCoeff();
  const Eigen::MatrixXd L = cov.llt().matrixL();
  const double pi = std::numbers::pi;
  const double unit_std = std::sqrt(2.0 * unit_diffusion(tau) * d) / pi;  // of mode 1
  InputSignal in;
  in.columns = 3 * K * (1 + M);
  in.at = [&, drive, K, M, d](double t, Columns3& accel, Columns3& angle) {
    accel.setZero();
    angle.setZero();
    Columns3& out = drive == Drive::kAccel || drive == Drive::kVelocity ? accel : angle;
    for (int j = 0; j < K; ++j) {
      const double u = t - (tk[j] - d);  // time into interval j
      double knot = 0.0;
      switch (drive) {
        case Drive::kAccel: case Drive::kAngle: knot = hat(t, tk[j], d); break;
        case Drive::kRate: knot = hat_integral(t, tk[j], d); break;  // θ = ∫ ω
        case Drive::kVelocity:  // a = dv/dt
          knot = (t > tk[j] - d && t <= tk[j]) ? 1.0 / d : (t > tk[j] && t <= tk[j] + d) ? -1.0 / d : 0.0;
          break;
      }
      for (int k = 0; k < 3; ++k) out(k, 3 * j + k) = knot;
      if (u <= 0) continue;
      for (int m = 1; m <= M; ++m) {
        const double w = m * pi / d;
        double mode = 0.0;
        switch (drive) {
          case Drive::kAccel: case Drive::kAngle: mode = u < d ? std::sin(w * u) : 0.0; break;
          case Drive::kRate: mode = (1.0 - std::cos(w * std::min(u, d))) / w; break;
          case Drive::kVelocity: mode = u < d ? w * std::cos(w * u) : 0.0; break;
        }
        for (int k = 0; k < 3; ++k) out(k, 3 * (K * m + j) + k) = unit_std / m * mode;
      }
    }
  };
  Eigen::MatrixXd r = input_response(*ctx.layout, *ctx.site, in);
  // Knot columns per axis k: r(:, 3j + k); mix the knots by L.
  for (int k = 0; k < 3; ++k) {
    Eigen::MatrixXd axis(r.rows(), K);
    for (int j = 0; j < K; ++j) axis.col(j) = r.col(3 * j + k);
    const Eigen::MatrixXd mixed = axis * L;
    for (int j = 0; j < K; ++j) r.col(3 * j + k) = mixed.col(j);
  }
  ctx.cache[key] = r;
  return r;
}

/// Noise added to the f rows (per axis weight) [ (m/s²)² ].
Eigen::VectorXd f_noise(const LayoutContext& ctx, const Eigen::Vector3d& var) {
  Eigen::VectorXd add = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(ctx.layout->rows.size()));
  for (std::size_t i = 0; i < ctx.layout->rows.size(); ++i) {
    const ObservationRow& r = ctx.layout->rows[i];
    if (r.quantity == Quantity::kF) add[static_cast<Eigen::Index>(i)] = var[r.axis];
  }
  return add;
}

/// A random process on the knots with σ = params[0], τ = params[1].
Extension process_extension(const LayoutContext& ctx, Drive drive, double sigma, double tau) {
  Extension e;
  // A Gauss–Markov process has its stationary σ already at switch-over: the
  // alignment takes that value for δf or ω_do, beyond Table 3.1's.
  if (tau > 0 && drive == Drive::kAccel) e.x_var_add.segment<3>(ux::kAccelBias).setConstant(sigma * sigma);
  if (tau > 0 && drive == Drive::kRate) e.x_var_add.segment<3>(ux::kGyroDrift).setConstant(sigma * sigma);
  e.columns = process_columns(ctx, drive, tau);
  e.column_var = Eigen::VectorXd::Constant(e.columns.cols(), sigma * sigma);
  // The bridges' higher modes, seen by the f rows only: of the process
  // itself (accelerometer) or of g × θ (a tilt on the horizontal axes).
  const double rest = bridge_rest_share(kBridgeModes) * sigma * sigma * unit_diffusion(tau) * knot_spacing(tau);
  const double g = ctx.site->model.gravity_mps2;
  if (drive == Drive::kAccel) e.noise_var_add = f_noise(ctx, Eigen::Vector3d::Constant(rest));
  if (drive == Drive::kAngle) e.noise_var_add = f_noise(ctx, Eigen::Vector3d(g * g * rest, g * g * rest, 0.0));
  return e;
}

/// Columns of a deterministic signature with amplitude prior params (one
/// column per axis unless `shared`).
Eigen::MatrixXd signature_columns(const LayoutContext& ctx, const std::string& key, int columns,
                                  const std::function<void(double, Columns3&, Columns3&)>& at) {
  if (auto it = ctx.cache.find(key); it != ctx.cache.end()) return it->second;
  InputSignal in;
  in.columns = columns;
  in.at = at;
  Eigen::MatrixXd r = input_response(*ctx.layout, *ctx.site, in);
  ctx.cache[key] = r;
  return r;
}

/// f^{a'}(t) = −C(t) g_e, the specific force at rest in a' (3.24).
Eigen::Vector3d specific_force(double t, const ModelOptions& m) { return -gravity_in_ap(t, m); }

/// ∫_0^t of a smooth vector function by a table at 10 s (Simpson per step), linear between.
class IntegralTable {
 public:
  IntegralTable(const std::function<Eigen::Vector3d(double)>& f, double end_s) {
    values_.push_back(Eigen::Vector3d::Zero());
    for (double t = 0; t < end_s + kStep; t += kStep)
      values_.push_back(values_.back() + kStep / 6.0 * (f(t) + 4.0 * f(t + kStep / 2) + f(t + kStep)));
  }
  Eigen::Vector3d at(double t) const {
    const double u = std::clamp(t / kStep, 0.0, static_cast<double>(values_.size() - 1) - 1e-9);
    const auto i = static_cast<std::size_t>(u);
    const double w = u - static_cast<double>(i);
    return (1 - w) * values_[i] + w * values_[std::min(i + 1, values_.size() - 1)];
  }
 private:
  static constexpr double kStep = 10.0;
  std::vector<Eigen::Vector3d> values_;
};

Candidate bounds() {
  return {"bounds", "priors wider than Table 3.1: every uncertainty's variance times s²",
          {{"scale", Dimension::kDimensionless, {1.5, 2, 3, 5, 10, 30, 100, 300, 1000}}},
          [](const LayoutContext&, std::span<const double> p) {
            Extension e;
            e.x_var_scale = UncertaintyVector::Constant(p[0] * p[0]);
            return e;
          }};
}

Candidate quantization() {
  return {"quantization",
          "ΔV pulses of another weight than the model's: counting noise w²/(6τ²) in f, and in r the pulse phase and "
          "the slow sawtooth of the counters' velocity error (pulse_counting.h)",
          {{"dv_pulse", Dimension::kVelocity, log_grid(0.02, 5, 1.0)}},
          [](const LayoutContext& ctx, std::span<const double> p) {
            Extension e;
            e.counting = pulse_counting(*ctx.layout, *ctx.site, p[0], ctx.base->x_var, ctx.base->noise_var.cwiseSqrt());
            return e;
          }};
}

Candidate sway() {
  return {"sway",
          "vehicle sway of periods 2-20 s: residual acceleration in f after the τ box filter, its velocity and "
          "displacement at switch-over, and the counters cycling from the start",
          {{"accel_rms", Dimension::kAcceleration, log_grid(0.2, 200, kMgToMps2)}},
          [](const LayoutContext& ctx, std::span<const double> p) {
            // Log-uniform periods in [2, 20] s: mean power gain of the box
            // filter sinc²(π τ/P), mean 1/ω² for the velocity and 1/ω⁴ for
            // the displacement.
            constexpr double p1 = 2.0, p2 = 20.0, vertical = 0.3;
            const double tau = ctx.site->filter_interval_s, two_pi = 2.0 * std::numbers::pi;
            double gain = 0.0;
            constexpr int n = 200;
            for (int i = 0; i < n; ++i) {
              const double period = p1 * std::pow(p2 / p1, (i + 0.5) / n);
              const double x = std::numbers::pi * tau / period;
              gain += std::pow(std::sin(x) / x, 2) / n;
            }
            const double inv_w2 = (p2 * p2 - p1 * p1) / (2 * std::log(p2 / p1)) / std::pow(two_pi, 2);
            const double inv_w4 = (std::pow(p2, 4) - std::pow(p1, 4)) / (4 * std::log(p2 / p1)) / std::pow(two_pi, 4);
            const double a2 = p[0] * p[0];
            const Eigen::Vector3d axes(1, 1, vertical * vertical);
            Extension e;
            e.noise_var_add = f_noise(ctx, a2 * gain * axes);
            e.x_var_add.segment<3>(ux::kInitialVelocity) = a2 * inv_w2 * axes;
            // The displacement at switch-over is an initial position error the
            // computer does not know: r = r0 cos(ω_s t) (3.24). Table 3.1 has
            // one north (δL0) and down (δh), none east.
            // After a reset the computer takes its stationary position again;
            // after a realignment a new displacement is its own cause.
            const Layout& l = *ctx.layout;
            const bool restart = l.nav == NavSegment::kRestart;
            e.columns = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(l.rows.size()), restart ? 6 : 3);
            const double ws = ctx.site->model.schuler_radps();
            for (std::size_t i = 0; i < l.rows.size(); ++i) {
              const ObservationRow& row = l.rows[i];
              const bool nav = static_cast<int>(i) >= l.test_rows;
              if (row.quantity != Quantity::kR || (nav && l.nav == NavSegment::kReset)) continue;
              e.columns(static_cast<Eigen::Index>(i), row.axis + (l.restarted(i) ? 3 : 0)) = std::cos(ws * l.clock_s(i));
            }
            e.column_var = (a2 * inv_w4 * axes).replicate(restart ? 2 : 1, 1);
            // The counters count the sway too (pulse_counting.h).
            CountedMotion motion;
            motion.velocity_rms_mps = p[0] * std::sqrt(inv_w2) * axes.cwiseSqrt();
            e.counting = pulse_counting(*ctx.layout, *ctx.site, ctx.site->dv_pulse_mps, ctx.base->x_var,
                                        ctx.base->noise_var.cwiseSqrt(), motion);
            return e;
          }};
}

Candidate accel_bias_instability() {
  return {"accel_bias_instability",
          "accelerometer bias wandering as a random walk (tau 0, σ after 1 h) or Gauss–Markov process",
          {{"sigma", Dimension::kAcceleration, log_grid(2, 2000, kUg)},
           {"tau", Dimension::kTime, {0.0, 300.0, 1200.0, 3600.0}}},
          [](const LayoutContext& ctx, std::span<const double> p) {
            return process_extension(ctx, Drive::kAccel, p[0], p[1]);
          }};
}

Candidate gyro_drift_instability() {
  return {"gyro_drift_instability",
          "gyro drift wandering as a random walk (tau 0, σ after 1 h) or Gauss–Markov process",
          {{"sigma", Dimension::kAngularRate, log_grid(0.1, 100, kMeruToRadps)},
           {"tau", Dimension::kTime, {0.0, 300.0, 1200.0, 3600.0}}},
          [](const LayoutContext& ctx, std::span<const double> p) {
            return process_extension(ctx, Drive::kRate, p[0], p[1]);
          }};
}

Candidate angle_random_walk() {
  return {"angle_random_walk", "white gyro rate noise: the platform angle walks (σ after 1 h)",
          {{"angle_1h", Dimension::kAngle, log_grid(0.005, 10, kMradToRad)}},
          [](const LayoutContext& ctx, std::span<const double> p) {
            return process_extension(ctx, Drive::kAngle, p[0], 0.0);
          }};
}

Candidate velocity_random_walk() {
  return {"velocity_random_walk",
          "white accelerometer noise: white in f (q/τ), a velocity random walk in r (σ after 1 h)",
          {{"velocity_1h", Dimension::kVelocity, log_grid(0.01, 10, 1.0)}},
          [](const LayoutContext& ctx, std::span<const double> p) {
            // The walk's increments over τ that the knots and bridge modes
            // do not carry are white in f: q/τ.
            Extension e = process_extension(ctx, Drive::kVelocity, p[0], 0.0);
            const double q = p[0] * p[0] / 3600.0;
            e.noise_var_add = f_noise(ctx, Eigen::Vector3d::Constant(q / ctx.site->filter_interval_s));
            return e;
          }};
}

Candidate thermal_transient() {
  return {"thermal_transient",
          "bias and drift settling exponentially after switch-on, the same in every run (a design effect): "
          "a(t) = b (e^{-t/tau} − 1), θ(t) = d (tau (1 − e^{-t/tau}) − t) on every axis; b, d at switch-over",
          {{"bias", Dimension::kAcceleration, {10 * kMgToMps2}, true},
           {"drift", Dimension::kAngularRate, {300 * kMeruToRadps}, true},
           {"tau", Dimension::kTime, {600.0, 1200.0, 2400.0}}},
          [](const LayoutContext& ctx, std::span<const double> p) {
            const double tau = p[2];
            const Eigen::MatrixXd cols = signature_columns(ctx, "thermal:" + std::to_string(tau), 2,
                                                           [tau](double t, Columns3& a, Columns3& th) {
                                                             const double decay = std::exp(-t / tau);
                                                             a.setZero();
                                                             th.setZero();
                                                             a.col(0).setConstant(decay - 1.0);
                                                             th.col(1).setConstant(tau * (1.0 - decay) - t);
                                                           });
            // b(t) = b0 + b0 (e^{-t/tau} − 1): the part at switch-over acts as
            // the fixed bias δf and drift ω_do do, through the alignment (their
            // columns of H_x); the settling is the signature above.
            const Eigen::MatrixXd& H = ctx.base->H_x;
            const Eigen::VectorXd fixed_bias = H.middleCols<3>(ux::kAccelBias).rowwise().sum();
            const Eigen::VectorXd fixed_drift = H.middleCols<3>(ux::kGyroDrift).rowwise().sum();
            Extension e;
            e.mean = p[0] * (cols.col(0) + fixed_bias) + p[1] * (cols.col(1) + fixed_drift);
            return e;
          }};
}
Candidate anisoelastic_drift() {
  return {"anisoelastic_drift",
          "g²-sensitive drift ω = c (f_y f_z, f_z f_x, f_x f_y)/g² as the earth turns gravity in the platform, the "
          "same in every run (a design effect)",
          {{"coefficient", Dimension::kAngularRate, {1000 * kMeruToRadps}, true}},
          [](const LayoutContext& ctx, std::span<const double> p) {
            const ModelOptions m = ctx.site->model;
            const double g2 = m.gravity_mps2 * m.gravity_mps2;
            const IntegralTable theta(
                [&](double t) -> Eigen::Vector3d {
                  const Eigen::Vector3d f = specific_force(t, m);
                  return Eigen::Vector3d(f.y() * f.z(), f.z() * f.x(), f.x() * f.y()) / g2;
                },
                layout_end(*ctx.layout) + 60.0);
            Extension e;
            e.mean = p[0] * signature_columns(ctx, "anisoelastic", 1, [&](double t, Columns3& a, Columns3& th) {
                              a.setZero();
                              th.col(0) = theta.at(t);
                            }).col(0);
            return e;
          }};
}
Candidate scale_factor_nonlinearity() {
  return {"scale_factor_nonlinearity",
          "accelerometer output k2 (f_k/g)² on every axis as the earth turns gravity in the platform, the same in "
          "every run (a design effect)",
          {{"k2", Dimension::kAcceleration, {20 * kMgToMps2}, true}},
          [](const LayoutContext& ctx, std::span<const double> p) {
            const ModelOptions m = ctx.site->model;
            const Eigen::Vector3d f0 = specific_force(0.0, m);
            const double g2 = m.gravity_mps2 * m.gravity_mps2;
            // The value at switch-over acts as a fixed bias δf through the
            // alignment (its H_x columns); the change as gravity turns is the signature.
            Eigen::VectorXd at_switch = Eigen::VectorXd::Zero(ctx.base->H_x.rows());
            for (int k = 0; k < 3; ++k) at_switch += f0[k] * f0[k] / g2 * ctx.base->H_x.col(ux::kAccelBias + k);
            Extension e;
            e.mean = p[0] * (at_switch + signature_columns(ctx, "sfn", 1, [m, f0, g2](double t, Columns3& a, Columns3& th) {
                                           th.setZero();
                                           const Eigen::Vector3d f = specific_force(t, m);
                                           a.col(0) = (f.array().square() - f0.array().square()).matrix() / g2;
                                         }).col(0));
            return e;
          }};
}
Candidate deflection_of_vertical() {
  return {"deflection_of_vertical",
          "deflection of the vertical at the site beyond Table 3.1, the same in every run: ξ, η of (2.8b) with a "
          "fixed value",
          {{"xi", Dimension::kAngle, {20 * kMradToRad}, true},
           {"eta", Dimension::kAngle, {20 * kMradToRad}, true}},
          [](const LayoutContext& ctx, std::span<const double> p) {
            Extension e;
            e.mean = p[0] * ctx.base->H_x.col(ux::kDeflection) + p[1] * ctx.base->H_x.col(ux::kDeflection + 1);
            return e;
          }};
}
Candidate gravity_model() {
  return {"gravity_model",
          "the computer's gravitation differs from the true one (e.g. J2), the same in every run at a site: the "
          "computer places the site where its own model has the plumb line the leveling found, an offset fixed "
          "to the earth (north, down; turning with it in a'), and lacks a vertical anomaly that drives r",
          {{"north_offset", Dimension::kLength, {1000e3}, true},
           {"down_offset", Dimension::kLength, {1000e3}, true},
           {"vertical", Dimension::kAcceleration, {100 * kMgToMps2}, true}},
          [](const LayoutContext& ctx, std::span<const double> p) {
            const ModelOptions m = ctx.site->model;
            InputSignal in;
            in.columns = 1;
            in.f_responds = false;
            // (3.24): the computer lacks δg_D, fixed to the earth: u = C(t) (0, 0, δg_D);
            // f is measured against the leveled plumb line, so only r sees it.
            in.at = [m](double t, Columns3& a, Columns3& th) {
              th.setZero();
              a.col(0) = C_ap_n(m.latitude_rad, m.earth_rate_radps * t).col(2);
            };
            const auto key = std::string("vertical_anomaly");
            if (!ctx.cache.count(key)) ctx.cache[key] = input_response(*ctx.layout, *ctx.site, in);
            Extension e;
            e.mean = p[2] * ctx.cache[key].col(0);
            // The site offset: a position error fixed to the earth, r(t) = C(t) (d_N, 0, d_D) in a'.
            for (std::size_t i = 0; i < ctx.layout->rows.size(); ++i) {
              const ObservationRow& row = ctx.layout->rows[i];
              if (row.quantity != Quantity::kR) continue;
              const Eigen::Matrix3d C = C_ap_n(m.latitude_rad, m.earth_rate_radps * row.t_s);
              e.mean[static_cast<Eigen::Index>(i)] += p[0] * C(row.axis, 0) + p[1] * C(row.axis, 2);
            }
            return e;
          }};
}

Candidate alignment_transient() {
  return {"alignment_transient",
          "alignment loops not settled at switch-over: a level and an azimuth misalignment beyond ζ_r",
          {{"level", Dimension::kAngle, scaled({0, 0.03, 0.1, 0.3, 1, 3}, kMradToRad)},
           {"azimuth", Dimension::kAngle, scaled({0.3, 1, 3, 10, 30, 100}, kMradToRad)}},
          [](const LayoutContext&, std::span<const double> p) {
            Extension e;
            e.x_var_add.segment<3>(ux::kMisalignAlign) = Eigen::Vector3d(p[0] * p[0], p[0] * p[0], p[1] * p[1]);
            return e;
          }};
}

Candidate switch_transient() {
  return {"switch_transient",
          "steps at switch-over beyond Table 3.1: misalignment (all axes) and accelerometer bias",
          {{"misalignment", Dimension::kAngle, scaled({0, 0.03, 0.1, 0.3, 1, 3, 10}, kMradToRad)},
           {"bias", Dimension::kAcceleration, scaled({0, 20, 50, 100, 200, 500, 1000, 3000}, kUg)}},
          [](const LayoutContext&, std::span<const double> p) {
            Extension e;
            e.x_var_add.segment<3>(ux::kMisalignAlign).setConstant(p[0] * p[0]);
            e.x_var_add.segment<2>(ux::kBiasChangeAlign).setConstant(p[1] * p[1]);
            e.x_var_add[ux::kAccelBias + 2] = p[1] * p[1];
            return e;
          }};
}

Candidate nonlinearity() {
  return {"nonlinearity",
          "terms the linear level drops (products of uncertainties, finite rotations): a model error "
          "of a share of the predicted position error",
          {{"share", Dimension::kDimensionless, {0.01, 0.03, 0.1, 0.3}}},
          [](const LayoutContext& ctx, std::span<const double> p) {
            Extension e;
            e.noise_var_add = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(ctx.layout->rows.size()));
            for (std::size_t i = 0; i < ctx.layout->rows.size(); ++i)
              if (ctx.layout->rows[i].quantity == Quantity::kR)
                e.noise_var_add[static_cast<Eigen::Index>(i)] = std::pow(p[0] * ctx.base->prior_std[static_cast<Eigen::Index>(i)], 2);
            return e;
          }};
}

}  // namespace

int Candidate::grid_size() const {
  int n = 1;
  for (const CandidateParameter& p : parameters)
    if (!p.amplitude) n *= static_cast<int>(p.grid.size());
  return n;
}

std::vector<double> Candidate::grid_point(int index) const {
  std::vector<double> v(parameters.size(), 0.0);
  for (std::size_t i = parameters.size(); i-- > 0;) {
    if (parameters[i].amplitude) continue;
    const int n = static_cast<int>(parameters[i].grid.size());
    v[i] = parameters[i].grid[static_cast<std::size_t>(index % n)];
    index /= n;
  }
  return v;
}

std::vector<int> Candidate::amplitude_indices() const {
  std::vector<int> out;
  for (std::size_t i = 0; i < parameters.size(); ++i)
    if (parameters[i].amplitude) out.push_back(static_cast<int>(i));
  return out;
}

const std::vector<Candidate>& candidate_registry() {
  static const std::vector<Candidate> all = {
      bounds(), quantization(), sway(), accel_bias_instability(), gyro_drift_instability(),
      angle_random_walk(), velocity_random_walk(), thermal_transient(), anisoelastic_drift(),
      scale_factor_nonlinearity(), deflection_of_vertical(), gravity_model(), alignment_transient(), switch_transient(),
      nonlinearity()};
  return all;
}

}  // namespace insmc::gap
