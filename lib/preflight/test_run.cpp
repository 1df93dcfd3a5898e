#include "lib/preflight/test_run.h"

#include <Eigen/QR>
#include <cmath>
#include <fmt/format.h>

#include "lib/common/assert.h"
#include "lib/common/input_error.h"
#include "lib/frames/frames.h"
#include "lib/preflight/observables.h"
#include "lib/propagation/linear_model.h"
#include "lib/propagation/paper_model.h"
#include "lib/units/quantity.h"

namespace insmc {

int TestRunOptions::intervals() const {
  // The windows that end within the test run: T/τ itself where τ divides T
  // (validate() asks it of a study); a recorder's τ need not.
  return static_cast<int>(std::floor(duration_s / filter_interval_s + 1e-6));
}

void validate(const TestRunOptions& o) {
  namespace r = test_run_range;
  require_in_range("--test-duration", o.duration_s, Dimension::kTime, r::kDuration);
  require_in_range("--filter-interval", o.filter_interval_s, Dimension::kTime, r::kFilterInterval);
  if (o.filter_interval_s > o.duration_s)
    throw InputError("--filter-interval", format_quantity(o.filter_interval_s, Dimension::kTime),
                     "must not exceed the test duration");
  const double k = o.duration_s / o.filter_interval_s;
  if (std::abs(k - std::round(k)) > 1e-6)
    throw InputError("--test-duration", format_quantity(o.duration_s, Dimension::kTime),
                     "must be a whole number of filter intervals");
  if (k < 4)
    throw InputError("--filter-interval", format_quantity(o.filter_interval_s, Dimension::kTime),
                     "leaves fewer than 4 intervals in the test run");
  require_in_range("--dv-pulse", o.dv_pulse_mps, Dimension::kVelocity, r::kDvPulse, "0 = continuous");
  require_in_range("--position-resolution", o.position_resolution_m, Dimension::kLength, r::kPositionResolution,
                   "0 = exact");
  require_in_range("--alignment-average", o.alignment_average_s, Dimension::kTime, r::kAlignmentAverage);
  require_in_range("--torquer-pulse", o.torquer_pulse_rad, Dimension::kAngle, r::kTorquerPulse, "0 = exact");
  require_in_range("--realignment-duration", o.realignment_duration_s, Dimension::kTime, r::kRealignmentDuration);
  require_in_range("--sway velocity", o.sway.velocity_rms_mps, Dimension::kVelocity, r::kSwayVelocity);
  require_in_range("--sway time", o.sway.correlation_time_s, Dimension::kTime, r::kSwayCorrelationTime);
  if (o.alignment_loops) validate(*o.alignment_loops);
}

Vec3 nominal_velocity_increment(double t, const ModelOptions& m) {
  const double w = m.earth_rate_radps, p = w * t;
  const double s = std::sin(m.latitude_rad), c = std::cos(m.latitude_rad);
  const double v = t - std::sin(p) / w, c1 = (1 - std::cos(p)) / w;
  // ∫ −C_n^{a'} g_e dt with the third column of B (3.5).
  return m.gravity_mps2 * Vec3(v * s * c, c1 * c, v * c * c - t);
}

Vec3 true_position_ap(double t, const ModelOptions& m) {
  const double p = m.earth_rate_radps * t, cL = std::cos(m.latitude_rad), sL = std::sin(m.latitude_rad);
  const Vec3 r_i = m.radius_m * Vec3(cL * std::cos(p), cL * std::sin(p), sL);
  return C_ap_i(m.latitude_rad) * r_i;
}

TestRunMaps test_run_maps(System system, Fidelity fidelity, const ModelOptions& m, const TestRunOptions& o) {
  TestRunMaps maps;
  const int K = o.intervals();
  for (int k = 0; k <= K; ++k) maps.t_s.push_back(k * o.filter_interval_s);
  if (fidelity == Fidelity::kPaper) {
    const ShortRunMatrices sr = paper_short_run_matrices(system, m);
    const Sensitivity3 a1 = paper_a1(sr, m);
    const double g = m.gravity_mps2, w = m.earth_rate_radps;
    for (double t : maps.t_s) {
      // (4.4) integrated: g{A1 t + U3 ω t²/2 + U4 ω² t³/6}; (3.29) less δr(0).
      maps.velocity_increment.push_back(g * (t * a1 + w * t * t / 2 * sr.u3 + w * w * t * t * t / 6 * sr.u4));
      maps.position_change.push_back(short_run_position_map(sr, t, m) - sr.initial_position_m);
    }
    return maps;
  }
  const LinearErrorModel model(system, m);
  const auto positions = linear_position_maps(model, maps.t_s);
  Sensitivity3 v = Sensitivity3::Zero();
  maps.velocity_increment.push_back(v);
  constexpr int kSimpson = 8;  // panels per interval: u(t) varies on 1/ω_ie ≫ τ
  for (int k = 1; k <= K; ++k) {
    const double a = maps.t_s[k - 1], h = (maps.t_s[k] - a) / kSimpson;
    Sensitivity3 sum = model.forcing(a) + model.forcing(maps.t_s[k]);
    for (int i = 1; i < kSimpson; ++i) sum += (i % 2 ? 4.0 : 2.0) * model.forcing(a + i * h);
    v += h / 3 * sum;
    maps.velocity_increment.push_back(v);
  }
  for (const auto& p : positions) maps.position_change.push_back(p - model.initial_position());
  return maps;
}

namespace {

/// (HᵀH)⁻¹Hᵀ by QR of H with unit-norm columns (the columns span many
/// orders of magnitude), rows of the result scaled back. Up to 2048 rows
/// (every study: at most 1800 intervals) by solving for every unit datum,
/// the K × K identity, as the study's results have always been computed;
/// beyond, as R⁻¹Q₁ᵀ (Q₁ the first p columns of Q, K × p), in K·p²
/// operations and K·p doubles: the identity took 1.3 GB and most of
/// `simulate`'s time at K = 9000 (τ = 0.1 s) and more memory than the
/// machine has at 2 h.
Eigen::MatrixXd least_squares_map(const Eigen::MatrixXd& h) {
  constexpr Eigen::Index kIdentityRows = 2048;
  const Eigen::VectorXd norms = h.colwise().norm().transpose();
  const Eigen::MatrixXd scaled = h * norms.cwiseInverse().asDiagonal();
  const Eigen::HouseholderQR<Eigen::MatrixXd> qr(scaled);
  if (h.rows() <= kIdentityRows) {
    const Eigen::MatrixXd identity = Eigen::MatrixXd::Identity(h.rows(), h.rows());
    const Eigen::MatrixXd pinv = qr.solve(identity);  // least-squares solution for each unit datum
    return norms.cwiseInverse().asDiagonal() * pinv;
  }
  const Eigen::Index p = h.cols();
  const Eigen::MatrixXd q1 = qr.householderQ() * Eigen::MatrixXd::Identity(h.rows(), p);
  const Eigen::MatrixXd r = qr.matrixQR().topLeftCorner(p, p).triangularView<Eigen::Upper>();
  const Eigen::MatrixXd pinv = r.triangularView<Eigen::Upper>().solve(q1.transpose());
  return norms.cwiseInverse().asDiagonal() * pinv;
}

}  // namespace

TestRunEstimators make_estimators(const TestRunOptions& o, const ModelOptions& m, bool u3_resolvable,
                                  bool u4_resolvable, const ObservedIntervals& observed) {
  TestRunEstimators e;
  e.fit_u3 = u3_resolvable;
  e.fit_u4 = u3_resolvable && u4_resolvable && o.fit_u4 != FitU4::kNo;
  if (o.fit_u4 == FitU4::kYes && !(u3_resolvable && u4_resolvable))
    throw InputError("--fit-u4", "yes",
                     fmt::format("U4 is not resolvable with T = {} and ΔV = {}: its (4.6) limit exceeds its prior "
                                 "RMS (Table 4.3); use --fit-u4 auto or a longer test",
                                 format_quantity(o.duration_s, Dimension::kTime),
                                 format_quantity(o.dv_pulse_mps, Dimension::kVelocity)));
  const int K = o.intervals();
  const double w = m.earth_rate_radps, ws = m.schuler_radps(), r0 = m.radius_m, g = m.gravity_mps2;
  const double q = w / ws;
  std::vector<int> pos_cols = {0, 1}, acc_cols = {0};
  if (e.fit_u3) pos_cols.push_back(2), acc_cols.push_back(1);
  if (e.fit_u4) pos_cols.push_back(3), acc_cols.push_back(2);
  Eigen::MatrixXd hp(K, pos_cols.size()), ha(K, acc_cols.size());
  for (int k = 1; k <= K; ++k) {
    const double t = k * o.filter_interval_s, a = t - o.filter_interval_s, x = ws * t;
    // (4.7) with the U4 term of (4.5).
    const double pos[4] = {std::sin(x) / ws, r0 * (1 - std::cos(x)), r0 * q * (x - std::sin(x)),
                           r0 * q * q * (0.5 * x * x - (1 - std::cos(x)))};
    // (4.4) averaged over the filter interval [a, t].
    const double acc[3] = {g, g * w * (a + t) / 2, g * w * w * (a * a + a * t + t * t) / 6};
    for (size_t j = 0; j < pos_cols.size(); ++j) hp(k - 1, static_cast<Eigen::Index>(j)) = pos[pos_cols[j]];
    for (size_t j = 0; j < acc_cols.size(); ++j) ha(k - 1, static_cast<Eigen::Index>(j)) = acc[acc_cols[j]];
  }
  // An interval a run lacks is a row the fit does not have: zero in the
  // design, and its column of the estimator set to exactly zero below.
  const auto has = [&](const std::vector<bool>& mask, int k) { return mask.empty() || mask[static_cast<size_t>(k)]; };
  INSMC_ASSERT((observed.position.empty() || observed.position.size() == static_cast<size_t>(K)) &&
                   (observed.accel.empty() || observed.accel.size() == static_cast<size_t>(K)),
               "observed intervals of {} and {} for K = {}", observed.position.size(), observed.accel.size(), K);
  for (int k = 0; k < K; ++k) {
    if (!has(observed.position, k)) hp.row(k).setZero();
    if (!has(observed.accel, k)) ha.row(k).setZero();
  }
  Eigen::MatrixXd lp = least_squares_map(hp), la = least_squares_map(ha);
  for (int k = 0; k < K; ++k) {
    if (!has(observed.position, k)) lp.col(k).setZero();
    if (!has(observed.accel, k)) la.col(k).setZero();
  }
  e.position = Eigen::Matrix<double, 4, Eigen::Dynamic>::Zero(4, K);
  e.accel = Eigen::Matrix<double, 3, Eigen::Dynamic>::Zero(3, K);
  for (size_t j = 0; j < pos_cols.size(); ++j) e.position.row(pos_cols[j]) = lp.row(static_cast<Eigen::Index>(j));
  for (size_t j = 0; j < acc_cols.size(); ++j) e.accel.row(acc_cols[j]) = la.row(static_cast<Eigen::Index>(j));
  e.fitted_terms = std::string("U1,U2") + (e.fit_u3 ? ",U3" : "") + (e.fit_u4 ? ",U4" : "");
  return e;
}

Resolvability resolvable_terms(System system, const ModelOptions& m, const TestRunOptions& o,
                               const UncertaintyModel& u) {
  const ShortRunMatrices sr = paper_short_run_matrices(system, m);
  const ResolutionLimits lim = pulse_resolution_limits(o.dv_pulse_mps, o.duration_s, m);
  const UncertaintyVector var = u.variance() + u.mean().cwiseAbs2();
  auto prior_rms = [&](const Sensitivity3& map) {
    double worst = 0;
    for (int k = 0; k < 3; ++k) worst = std::max(worst, std::sqrt(map.row(k).cwiseAbs2().dot(var.transpose())));
    return worst;
  };
  Resolvability r{};
  r.u3_limit = lim.u3;
  r.u4_limit = lim.u4;
  r.u3_prior_rms = prior_rms(sr.u3);
  r.u4_prior_rms = prior_rms(sr.u4);
  r.u3 = lim.u3 < r.u3_prior_rms;
  r.u4 = lim.u4 < r.u4_prior_rms;
  return r;
}

}  // namespace insmc
