#include "montecarlo/records/gap/candidates/random_process.h"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "montecarlo/records/gap/candidates/common.h"

namespace insmc::gap::candidates {
namespace {

/// Knots t_j = j Δ, j = 1..K, covering the run (the value at 0 is the
/// alignment's: processes enter as changes since switch-over).
std::vector<double> knots(const runs::Layout& layout, double spacing_s) {
  std::vector<double> k;
  const double end = layout_end(layout);
  for (double t = spacing_s; t < end + spacing_s; t += spacing_s) k.push_back(t);
  return k;
}

/// Knot spacing for a process of correlation time tau (0: random walk): a
/// Gauss–Markov process is resolved by knots a correlation time apart (the
/// bridge modes below carry what lies between), within bounds that keep the
/// model small.
double knot_spacing(double tau, const runs::Layout& layout) {
  const double spacing = tau > 0 ? std::clamp(tau, kMinKnotSpacingS, kKnotSpacingS) : kMinKnotSpacingS;
  return std::max(spacing, layout_end(layout) / kMaxKnots);
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
/// 150 s knots (tests/unit/montecarlo/records/runs/model): a velocity random walk, which r sees
/// through one integration only, is the most demanding.
constexpr int kBridgeModes = 1;
double bridge_rest_share(int modes) {
  double share = 1.0 / 6.0;
  for (int m = 1; m <= modes; ++m) share -= 1.0 / (m * m * std::numbers::pi * std::numbers::pi);
  return share;
}

/// Unit response of a process on the knots, per axis k: columns
/// 3(1 + M) j + k (j < K) the knot values, mixed by the Cholesky factor of
/// their covariance, and 3((1 + M) j + m) + k bridge mode m (1-based) of
/// interval j; every coefficient is independent with variance σ². In the
/// order of time: a row sees no column of a later interval, so a test run
/// sees only the leading columns and the fit's matrices are theirs
/// (run_analysis.h).
Eigen::MatrixXd process_columns(const LayoutContext& ctx, Drive drive, double tau) {
  const std::string key = "process" + std::to_string(static_cast<int>(drive)) + ":" + std::to_string(tau);
  if (auto it = ctx.cache.find(key); it != ctx.cache.end()) return it->second;
  const runs::Layout& layout = *ctx.layout;
  if (layout.nav == runs::NavSegment::kRestart && layout.test_rows < static_cast<int>(layout.rows.size())) {
    // After a realignment the process is taken from the new switch-over,
    // independent of what the test run saw: columns of its own.
    const runs::Layout test = layout.test_part(), nav = layout.restarted_part();
    const Eigen::MatrixXd a = process_columns({&test, ctx.site, ctx.base, {}}, drive, tau);
    const Eigen::MatrixXd b = process_columns({&nav, ctx.site, ctx.base, {}}, drive, tau);
    Eigen::MatrixXd out = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(layout.rows.size()), a.cols() + b.cols());
    out.topLeftCorner(a.rows(), a.cols()) = a;
    out.bottomRightCorner(b.rows(), b.cols()) = b;
    ctx.cache[key] = out;
    return out;
  }
  const double d = knot_spacing(tau, *ctx.layout);
  const std::vector<double> tk = knots(*ctx.layout, d);
  const int K = static_cast<int>(tk.size()), M = kBridgeModes;
  Eigen::MatrixXd cov(K, K);
  for (int i = 0; i < K; ++i)
    for (int j = 0; j < K; ++j) cov(i, j) = change_covariance(tk[i], tk[j], tau);
  cov.diagonal().array() += 1e-12 * cov.diagonal().maxCoeff();
  const Eigen::MatrixXd L = cov.llt().matrixL();
  const double pi = std::numbers::pi;
  const double unit_std = std::sqrt(2.0 * unit_diffusion(tau) * d) / pi;  // of mode 1
  runs::InputSignal in;
  in.columns = 3 * K * (1 + M);
  in.at = [&, drive, K, M, d](double t, runs::Columns3& accel, runs::Columns3& angle) {
    accel.setZero();
    angle.setZero();
    runs::Columns3& out = drive == Drive::kAccel || drive == Drive::kVelocity ? accel : angle;
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
      for (int k = 0; k < 3; ++k) out(k, 3 * (1 + M) * j + k) = knot;
      if (u <= 0) continue;
      for (int m = 1; m <= M; ++m) {
        const double w = m * pi / d;
        double mode = 0.0;
        switch (drive) {
          case Drive::kAccel: case Drive::kAngle: mode = u < d ? std::sin(w * u) : 0.0; break;
          case Drive::kRate: mode = (1.0 - std::cos(w * std::min(u, d))) / w; break;
          case Drive::kVelocity: mode = u < d ? w * std::cos(w * u) : 0.0; break;
        }
        for (int k = 0; k < 3; ++k) out(k, 3 * ((1 + M) * j + m) + k) = unit_std / m * mode;
      }
    }
  };
  Eigen::MatrixXd r = input_response(*ctx.layout, *ctx.site, in);
  // Knot columns per axis k: r(:, 3(1 + M) j + k); mix the knots by L (lower
  // triangular: knot i takes the drives of knots j ≤ i, so the order of time stays).
  for (int k = 0; k < 3; ++k) {
    Eigen::MatrixXd axis(r.rows(), K);
    for (int j = 0; j < K; ++j) axis.col(j) = r.col(3 * (1 + M) * j + k);
    const Eigen::MatrixXd mixed = axis * L;
    for (int j = 0; j < K; ++j) r.col(3 * (1 + M) * j + k) = mixed.col(j);
  }
  ctx.cache[key] = r;
  return r;
}

}  // namespace

runs::Extension process_extension(const LayoutContext& ctx, Drive drive, double sigma, double tau) {
  runs::Extension e;
  // A Gauss–Markov process has its stationary σ already at switch-over: the
  // alignment takes that value for δf or ω_do, beyond Table 3.1's.
  if (tau > 0 && drive == Drive::kAccel) e.x_var_add.segment<3>(uncertainty_slot::kAccelBias).setConstant(sigma * sigma);
  if (tau > 0 && drive == Drive::kRate) e.x_var_add.segment<3>(uncertainty_slot::kGyroDrift).setConstant(sigma * sigma);
  e.columns = process_columns(ctx, drive, tau);
  e.column_var = Eigen::VectorXd::Constant(e.columns.cols(), sigma * sigma);
  // The bridges' higher modes, seen by the f rows only: of the process
  // itself (accelerometer) or of θ × f (a platform angle, through the
  // specific force of the row's time).
  // The f rows' knots: after a realignment those of the test part, the only
  // part with modelled f rows (process_columns spaces each part's own).
  const runs::Layout& layout = *ctx.layout;
  const bool restarted = layout.nav == runs::NavSegment::kRestart && layout.test_rows < static_cast<int>(layout.rows.size());
  const double spacing = knot_spacing(tau, restarted ? layout.test_part() : layout);
  const double rest = bridge_rest_share(kBridgeModes) * sigma * sigma * unit_diffusion(tau) * spacing;
  if (drive == Drive::kAccel) e.noise_var_add = f_noise(ctx, Eigen::Vector3d::Constant(rest));
  if (drive == Drive::kAngle) e.noise_var_add = tilt_f_noise(ctx, rest);
  if (drive == Drive::kRate) {
    // A drift's higher bridge modes turn the platform by ∫ω: on average over
    // an interval 3qΔ³ Σ_{m>M} (mπ)⁻⁴, and the odd ones leave an angle at
    // the interval's end that adds up from interval to interval,
    // 8qΔ³ Σ_{odd m>M} (mπ)⁻⁴ each. Invisible at the pulses' resolution,
    // they are what a continuous f record shows of a drift.
    const double q = sigma * sigma * unit_diffusion(tau), d3 = spacing * spacing * spacing;
    const double pi4 = std::pow(std::numbers::pi, 4);
    double all = 1.0 / 90.0, odd = 1.0 / 96.0;  // Σ (mπ)⁻⁴ over all m, over odd m
    for (int m = 1; m <= kBridgeModes; ++m) {
      all -= 1.0 / (m * m * m * m * pi4);
      if (m % 2) odd -= 1.0 / (m * m * m * m * pi4);
    }
    e.noise_var_add = tilt_f_noise(ctx, 3.0 * q * d3 * all, 8.0 * q * d3 * odd / spacing);
  }
  return e;
}

}  // namespace insmc::gap::candidates
