#include "lib/calibration/multiposition.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>
#include <boost/math/distributions/fisher_f.hpp>
#include <fmt/format.h>

namespace insmc::calibration {
namespace {

/// The accelerometer model (C.1) with parameters x = (b_a, s, α_xy, α_xz, α_yz).
Vec3 calibrated_accel(const Eigen::VectorXd& x, const Vec3& raw_mps2) {
  Mat3 m = Mat3::Identity();
  m(0, 0) += x[3];
  m(1, 1) += x[4];
  m(2, 2) += x[5];
  m(0, 1) = x[6];
  m(0, 2) = x[7];
  m(1, 2) = x[8];
  return m * (raw_mps2 - x.head<3>());  // (C.1)
}

constexpr char kAxis[] = "xyz";

CalibratedParameter parameter(std::string name, ParameterKind kind, const LeastSquaresFit& fit, Eigen::Index p,
                              double t) {
  CalibratedParameter c{std::move(name), kind};
  c.value_si = fit.x[p];
  c.sigma_si = std::sqrt(fit.covariance(p, p));
  c.lo_si = c.value_si - t * c.sigma_si;
  c.hi_si = c.value_si + t * c.sigma_si;
  c.vif = fit.vif[p];
  return c;
}

Vec3 mean_of(const std::vector<Vec3>& v, const StaticSegment& s) {
  Vec3 sum = Vec3::Zero();
  for (std::size_t k = s.begin; k < s.end; ++k) sum += v[k];
  return sum / static_cast<double>(s.end - s.begin);
}

/// The smallest eigenvalue of the mean outer product of the unit vectors
/// of `v` (1/3 when they are spread evenly over the sphere, 0 when they
/// lie in one plane).
double direction_spread(const std::vector<Vec3>& v) {
  Mat3 sum = Mat3::Zero();
  int n = 0;
  for (const Vec3& x : v)
    if (x.norm() > 0) sum += x.normalized() * x.normalized().transpose(), ++n;
  if (n == 0) return 0;
  return Eigen::SelfAdjointEigenSolver<Mat3>(sum / n).eigenvalues().minCoeff();
}


/// (C.1)-(C.2): ‖(I + M_a)(ā_i − b_a)‖ − g over the still attitudes.
FitSummary fit_accelerometers(const std::vector<Vec3>& mean_a, const MultipositionOptions& o, Eigen::VectorXd& x) {
  const std::size_t m = mean_a.size();
  const auto residuals = [&](const Eigen::VectorXd& p, Eigen::VectorXd& r) {
    for (std::size_t i = 0; i < m; ++i)
      r[static_cast<Eigen::Index>(i)] = calibrated_accel(p, mean_a[i]).norm() - o.gravity_mps2;
  };
  Eigen::VectorXd step(9);
  step << Eigen::Vector3d::Constant(1e-5 * o.gravity_mps2), Eigen::Vector3d::Constant(1e-6),
      Eigen::Vector3d::Constant(1e-6);
  const LeastSquaresFit fit = fit_least_squares(residuals, Eigen::VectorXd::Zero(9), m, step);
  x = fit.x;
  const double t = t_factor(o.confidence, fit.dof);
  FitSummary out;
  for (int i = 0; i < 3; ++i)
    out.parameters.push_back(parameter(fmt::format("accel_bias_{}", kAxis[i]), ParameterKind::kAccelBias, fit, i, t));
  for (int i = 0; i < 3; ++i)
    out.parameters.push_back(
        parameter(fmt::format("accel_scale_factor_{}", kAxis[i]), ParameterKind::kScaleFactor, fit, 3 + i, t));
  const char* angles[] = {"accel_misalignment_xy", "accel_misalignment_xz", "accel_misalignment_yz"};
  for (int i = 0; i < 3; ++i) out.parameters.push_back(parameter(angles[i], ParameterKind::kMisalignment, fit, 6 + i, t));
  out.residual_rms_si = fit.residual_rms;
  out.residuals = static_cast<int>(m);
  out.fitted = true;
  return out;
}

/// (C.3) per gyro axis k: ω̄_ik = b_k + Σ_j G_kj f_ij, with the F-test of
/// G's row k = 0 (3 and N − 4 degrees of freedom).
FitSummary fit_gyro_static(const std::vector<Vec3>& mean_w, const std::vector<Vec3>& f, const MultipositionOptions& o,
                           Vec3& bias, Mat3& g_sensitivity, std::vector<double>& p_values) {
  FitSummary out;
  const std::size_t m = mean_w.size();
  for (int k = 0; k < 3; ++k) {
    const auto residuals = [&](const Eigen::VectorXd& p, Eigen::VectorXd& r) {
      for (std::size_t i = 0; i < m; ++i)
        r[static_cast<Eigen::Index>(i)] = p[0] + p.tail<3>().dot(f[i]) - mean_w[i][k];
    };
    Eigen::VectorXd step(4);
    step << 1e-6, 1e-8, 1e-8, 1e-8;
    const LeastSquaresFit fit = fit_least_squares(residuals, Eigen::VectorXd::Zero(4), m, step);
    const double t = t_factor(o.confidence, fit.dof);
    out.parameters.push_back(parameter(fmt::format("gyro_bias_{}", kAxis[k]), ParameterKind::kGyroBias, fit, 0, t));
    for (int j = 0; j < 3; ++j)
      out.parameters.push_back(parameter(fmt::format("g_sensitivity_{}{}", kAxis[k], kAxis[j]),
                                         ParameterKind::kGSensitivity, fit, 1 + j, t));
    bias[k] = fit.x[0];
    g_sensitivity.row(k) = fit.x.tail<3>().transpose();
    // The bias-only model's residual sum: the scatter about the mean.
    double mean = 0, rss0 = 0;
    for (const Vec3& w : mean_w) mean += w[k] / static_cast<double>(m);
    for (const Vec3& w : mean_w) rss0 += (w[k] - mean) * (w[k] - mean);
    const double rss1 = fit.residual_rms * fit.residual_rms * fit.dof;
    const double stat = ((rss0 - rss1) / 3) / (rss1 / fit.dof);
    p_values.push_back(rss1 <= 0 ? (rss0 > 0 ? 0.0 : 1.0)  // an exact fit
                       : std::isfinite(stat) && stat > 0
                           ? boost::math::cdf(boost::math::complement(boost::math::fisher_f(3, fit.dof), stat))
                           : 1.0);
    out.residual_rms_si = std::max(out.residual_rms_si, fit.residual_rms);
  }
  out.residuals = static_cast<int>(3 * m);
  out.fitted = true;
  return out;
}

/// (C.4): each turn's gyro samples, with bias and g-sensitivity removed,
/// and the gravity directions before and after it.
struct Turn {
  std::vector<Vec3> rate_radps;  ///< ω_raw − b_g − G f
  std::vector<double> dt_s;
  Vec3 up_before, up_after;      ///< unit specific force of the attitudes on either side
};

FitSummary fit_gyro_turns(const std::vector<Turn>& turns, const MultipositionOptions& o) {
  const std::size_t m = 3 * turns.size();
  const auto residuals = [&](const Eigen::VectorXd& p, Eigen::VectorXd& r) {
    const Mat3 scale = Mat3::Identity() + Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(p.data());
    for (std::size_t i = 0; i < turns.size(); ++i) {
      // Body attitude C_{k+1} = C_k exp([ω_k dt_k]×); a vector fixed in
      // space is seen in the body as Δᵀ v, Δ the product of the increments.
      Mat3 delta = Mat3::Identity();
      for (std::size_t k = 0; k < turns[i].rate_radps.size(); ++k) {
        const Vec3 phi = scale * turns[i].rate_radps[k] * turns[i].dt_s[k];
        const double angle = phi.norm();
        if (angle > 0) delta = delta * Eigen::AngleAxisd(angle, phi / angle).toRotationMatrix();
      }
      r.segment<3>(static_cast<Eigen::Index>(3 * i)) = delta.transpose() * turns[i].up_before - turns[i].up_after;
    }
  };
  const LeastSquaresFit fit = fit_least_squares(residuals, Eigen::VectorXd::Zero(9), m, Eigen::VectorXd::Constant(9, 1e-6));
  FitSummary out;
  if (!fit.converged) {
    out.why_not = "the fit through the turns did not converge in 100 iterations";
    return out;
  }
  // Each residual has 2 degrees of freedom (the unit vectors' difference is
  // perpendicular to them to first order): the scatter per component uses
  // 2 × turns − 9.
  const int dof = static_cast<int>(2 * turns.size()) - 9;
  const double t = t_factor(o.confidence, dof);
  const double rescale = std::sqrt(static_cast<double>(fit.dof) / dof);
  LeastSquaresFit scaled = fit;
  scaled.covariance *= rescale * rescale;
  if (fit.residual_rms * rescale > kMaxTurnResidualRad) {
    out.why_not = fmt::format(
        "the gravity direction after each turn is off by {:.3g} mrad RMS after the fit (more than {:g}): check the "
        "gyro columns and their unit, or turns too fast for the sample rate",
        1e3 * fit.residual_rms * rescale, 1e3 * kMaxTurnResidualRad);
    return out;
  }
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c)
      out.parameters.push_back(
          r == c ? parameter(fmt::format("gyro_scale_factor_{}", kAxis[r]), ParameterKind::kScaleFactor, scaled, 3 * r + c, t)
                 : parameter(fmt::format("gyro_misalignment_{}{}", kAxis[r], kAxis[c]), ParameterKind::kMisalignment,
                             scaled, 3 * r + c, t));
  out.residual_rms_si = fit.residual_rms * rescale;
  out.residuals = static_cast<int>(m);
  out.fitted = true;
  return out;
}

}  // namespace

std::size_t distinct_directions(const std::vector<Vec3>& f, double same_rad) {
  std::vector<Vec3> seen;
  for (const Vec3& x : f) {
    if (!(x.norm() > 0)) continue;  // no direction (checked against gravity by the caller)
    const Vec3 u = x.normalized();
    if (std::none_of(seen.begin(), seen.end(), [&](const Vec3& v) { return u.dot(v) > std::cos(same_rad); }))
      seen.push_back(u);
  }
  return seen.size();
}

MultipositionCalibration calibrate_multiposition(const ImuSamples& s, const MultipositionOptions& o) {
  MultipositionCalibration c;
  c.segments = find_static_segments(s, o.detection);
  for (const StaticSegment& seg : c.segments) {
    c.segment_accel_mps2.push_back(mean_of(s.accel_b_mps2, seg));
    c.segment_gyro_radps.push_back(mean_of(s.gyro_b_radps, seg));
  }
  c.orientations = distinct_directions(c.segment_accel_mps2, o.same_orientation_rad);
  const std::size_t n = c.segments.size();
  const std::string too_few =
      fmt::format("{} still attitudes in {} orientations: a multi-position calibration needs {} attitudes in at "
                  "least 6 orientations",
                  n, c.orientations, kMinCalibrationSegments);
  if (n < kMinCalibrationSegments || c.orientations < 6) {
    c.accel.why_not = c.gyro_static.why_not = c.gyro_turns.why_not = too_few;
    return c;
  }
  // The attitudes must point gravity along every body axis: directions in
  // one plane (turns about one axis) leave the axis across it unseen.
  const double spread = direction_spread(c.segment_accel_mps2);
  if (spread < kMinDirectionSpread) {
    c.accel.why_not = c.gyro_static.why_not = c.gyro_turns.why_not = fmt::format(
        "the still attitudes' gravity directions lie nearly in one plane (smallest eigenvalue of their mean "
        "outer product {:.3g}, at least {:g} needed): turn the sensor so that every axis points up and down",
        spread, kMinDirectionSpread);
    return c;
  }
  // Gravity is the only reference: at rest the accelerometers must see
  // about its magnitude (a unit or column mistake otherwise).
  for (const Vec3& a : c.segment_accel_mps2)
    if (!(a.norm() > 0.5 * o.gravity_mps2 && a.norm() < 2 * o.gravity_mps2)) {
      c.accel.why_not = c.gyro_static.why_not = c.gyro_turns.why_not = fmt::format(
          "a still attitude's mean specific force is {:.4g} m/s², not near gravity ({:.6g} m/s²): check the "
          "accelerometer columns and their unit",
          a.norm(), o.gravity_mps2);
      return c;
    }
  Eigen::VectorXd accel_x;
  c.accel = fit_accelerometers(c.segment_accel_mps2, o, accel_x);
  std::vector<Vec3> f;
  for (const Vec3& a : c.segment_accel_mps2) f.push_back(calibrated_accel(accel_x, a));
  Vec3 gyro_bias;
  Mat3 g_sensitivity;
  c.gyro_static = fit_gyro_static(c.segment_gyro_radps, f, o, gyro_bias, g_sensitivity, c.g_sensitivity_p);
  std::vector<Turn> turns;
  std::vector<Vec3> turn_axes;
  for (std::size_t i = 0; i + 1 < n; ++i) {
    // A long motion between two attitudes (carried, not turned) would bring
    // its integrated gyro error into (C.4): left out.
    if (s.t_s[c.segments[i + 1].begin] - s.t_s[c.segments[i].end - 1] > kMaxTurnS) continue;
    Turn t;
    for (std::size_t k = c.segments[i].end; k < c.segments[i + 1].begin; ++k) {
      t.rate_radps.push_back(s.gyro_b_radps[k] - gyro_bias - g_sensitivity * calibrated_accel(accel_x, s.accel_b_mps2[k]));
      t.dt_s.push_back(s.end_s(k) - s.t_s[k]);
    }
    t.up_before = f[i].normalized();
    t.up_after = f[i + 1].normalized();
    Vec3 angle = Vec3::Zero();
    for (std::size_t k = 0; k < t.rate_radps.size(); ++k) angle += t.rate_radps[k] * t.dt_s[k];
    turn_axes.push_back(angle);
    turns.push_back(std::move(t));
  }
  // (C.4) sees a gyro's scale and misalignment only through turns about
  // its axis: the turns' rotation vectors must span all three.
  const double turn_spread = direction_spread(turn_axes);
  if (turns.size() < 6 || turn_spread < kMinDirectionSpread)
    c.gyro_turns.why_not = fmt::format(
        "{} turns of at most {:g} s between still attitudes, their axes' spread {:.3g} (at least 6 turns and {:g} "
        "needed): turn the sensor about each of its axes",
        turns.size(), kMaxTurnS, turn_spread, kMinDirectionSpread);
  else
    c.gyro_turns = fit_gyro_turns(turns, o);
  return c;
}

}  // namespace insmc::calibration
