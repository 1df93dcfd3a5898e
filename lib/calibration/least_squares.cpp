#include "lib/calibration/least_squares.h"

#include <cmath>
#include <limits>

#include <boost/math/distributions/students_t.hpp>

namespace insmc::calibration {
namespace {

Eigen::MatrixXd jacobian(const ResidualFunction& f, const Eigen::VectorXd& x, std::size_t m,
                         const Eigen::VectorXd& step) {
  Eigen::MatrixXd j(static_cast<Eigen::Index>(m), x.size());
  Eigen::VectorXd plus(static_cast<Eigen::Index>(m)), minus(static_cast<Eigen::Index>(m));
  Eigen::VectorXd xp = x;
  for (Eigen::Index p = 0; p < x.size(); ++p) {
    xp[p] = x[p] + step[p];
    f(xp, plus);
    xp[p] = x[p] - step[p];
    f(xp, minus);
    xp[p] = x[p];
    j.col(p) = (plus - minus) / (2 * step[p]);
  }
  return j;
}

}  // namespace

LeastSquaresFit fit_least_squares(const ResidualFunction& f, const Eigen::VectorXd& x0, std::size_t m,
                                  const Eigen::VectorXd& step) {
  const Eigen::Index n = x0.size();
  LeastSquaresFit fit;
  fit.x = x0;
  Eigen::VectorXd r(static_cast<Eigen::Index>(m)), trial_r(static_cast<Eigen::Index>(m));
  f(fit.x, r);
  double cost = r.squaredNorm(), lambda = 1e-3;
  for (fit.iterations = 0; fit.iterations < 100; ++fit.iterations) {
    const Eigen::MatrixXd j = jacobian(f, fit.x, m, step);
    const Eigen::MatrixXd jtj = j.transpose() * j;
    const Eigen::VectorXd g = j.transpose() * r;
    bool improved = false;
    // Levenberg–Marquardt: damp by the diagonal until the cost falls.
    for (int tries = 0; tries < 30 && !improved; ++tries) {
      Eigen::MatrixXd a = jtj;
      for (Eigen::Index p = 0; p < n; ++p) a(p, p) += lambda * std::max(jtj(p, p), 1e-300);
      const Eigen::VectorXd dx = -a.ldlt().solve(g);
      const Eigen::VectorXd trial = fit.x + dx;
      f(trial, trial_r);
      const double trial_cost = trial_r.squaredNorm();
      if (std::isfinite(trial_cost) && trial_cost <= cost) {
        const bool small = cost - trial_cost <= 1e-14 * cost || (dx.array().abs() <= 1e-9 * step.array()).all();
        fit.x = trial;
        r = trial_r;
        cost = trial_cost;
        lambda = std::max(lambda / 10, 1e-12);
        improved = true;
        if (small) fit.converged = true;
      } else {
        lambda *= 10;
      }
    }
    if (!improved) fit.converged = true;  // no step lowers the cost: at the minimum to working precision
    if (fit.converged) break;
  }
  fit.dof = static_cast<int>(m) - static_cast<int>(n);
  fit.residual_rms = fit.dof > 0 ? std::sqrt(cost / fit.dof) : std::numeric_limits<double>::quiet_NaN();
  // Covariance and variance inflation from the SVD of the column-scaled
  // Jacobian: a direction with a negligible singular value is not
  // determined, and every parameter that leans on it gets an infinite variance.
  const Eigen::MatrixXd j = jacobian(f, fit.x, m, step);
  Eigen::VectorXd scale(n);
  for (Eigen::Index p = 0; p < n; ++p) scale[p] = j.col(p).norm();
  Eigen::MatrixXd js = j;
  for (Eigen::Index p = 0; p < n; ++p)
    if (scale[p] > 0) js.col(p) /= scale[p];
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(js, Eigen::ComputeThinV);
  const Eigen::VectorXd s = svd.singularValues();
  const Eigen::MatrixXd& v = svd.matrixV();
  const double inf = std::numeric_limits<double>::infinity();
  fit.covariance = Eigen::MatrixXd::Zero(n, n);
  fit.vif = Eigen::VectorXd::Zero(n);
  for (Eigen::Index k = 0; k < n; ++k) {
    const bool null_direction = !(s[k] > 1e-9 * s[0]);
    for (Eigen::Index p = 0; p < n; ++p) {
      const double w = v(p, k) * v(p, k);
      if (null_direction) {
        if (w > 1e-12 || scale[p] == 0) fit.vif[p] = inf;
        continue;
      }
      fit.vif[p] += w / (s[k] * s[k]);
      for (Eigen::Index q = 0; q < n; ++q) fit.covariance(p, q) += v(p, k) * v(q, k) / (s[k] * s[k]);
    }
  }
  for (Eigen::Index p = 0; p < n; ++p)
    for (Eigen::Index q = 0; q < n; ++q)
      fit.covariance(p, q) = scale[p] > 0 && scale[q] > 0
                                 ? fit.covariance(p, q) * fit.residual_rms * fit.residual_rms / (scale[p] * scale[q])
                                 : 0;
  for (Eigen::Index p = 0; p < n; ++p)
    if (!std::isfinite(fit.vif[p]) || scale[p] == 0) fit.covariance(p, p) = inf;
  return fit;
}

double t_factor(double confidence, int dof) {
  if (dof <= 0) return std::numeric_limits<double>::infinity();
  return boost::math::quantile(boost::math::students_t(dof), 0.5 + confidence / 2);
}

}  // namespace insmc::calibration
