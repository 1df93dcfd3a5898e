#include "montecarlo/records/gap/ranking/estimate_naming.h"

#include <Eigen/Cholesky>
#include <Eigen/QR>
#include <algorithm>
#include <cmath>
#include <limits>

#include "montecarlo/records/gap/ranking/statements.h"

namespace insmc::gap {
namespace {

/// ½ χ²₁ at 95 %: a runner-up closer than this is not told apart.
constexpr double kClassNats = 1.92;

/// One point of a candidate's grid carried to the estimates: the added
/// covariance (in the null's, S = C0 + V) and the mean shift per amplitude.
struct EstimatePoint {
  Eigen::LLT<Eigen::MatrixXd> llt;
  double logdet = 0;
  Eigen::MatrixXd D;  ///< estimates × amplitudes
};

EstimatePoint make_point(const Eigen::MatrixXd& S, Eigen::MatrixXd D) {
  EstimatePoint pt;
  pt.llt.compute(S);
  pt.logdet = 2.0 * pt.llt.matrixL().toDenseMatrix().diagonal().array().log().sum();
  pt.D = std::move(D);
  return pt;
}

/// Least-squares amplitudes on the runs `r` (generalized by S⁻¹).
Eigen::VectorXd amplitudes(const EstimatePoint& pt, const Eigen::MatrixXd& z, const std::vector<int>& r) {
  if (pt.D.cols() == 0 || r.empty()) return Eigen::VectorXd::Zero(pt.D.cols());
  Eigen::VectorXd mean = Eigen::VectorXd::Zero(z.rows());
  for (const int i : r) mean += z.col(i);
  mean /= static_cast<double>(r.size());
  const Eigen::MatrixXd SiD = pt.llt.solve(pt.D);
  const Eigen::MatrixXd normal = pt.D.transpose() * SiD;
  return normal.completeOrthogonalDecomposition().solve(SiD.transpose() * mean);
}

double log_likelihood(const EstimatePoint& pt, const Eigen::VectorXd& a, const Eigen::MatrixXd& z,
                      const std::vector<int>& r) {
  double ll = 0;
  for (const int i : r) {
    const Eigen::VectorXd d = pt.D.cols() ? Eigen::VectorXd(z.col(i) - pt.D * a) : Eigen::VectorXd(z.col(i));
    ll -= 0.5 * (d.dot(pt.llt.solve(d)) + pt.logdet);
  }
  return ll;
}

bool acts_inside_priors(const runs::Extension& e) {
  return (e.columns.cols() == 0 || e.columns_higher_order) && e.noise_var_add.size() == 0 && !e.counting;
}

}  // namespace

void name_from_estimates(EstimateTest& test, const RunEstimates& e, const runs::PreparedRuns& p,
                         const runs::RunAnalyser& analyser, int layout, const std::vector<Candidate>& candidates) {
  const auto J = static_cast<Eigen::Index>(e.columns.size());
  const auto n = static_cast<int>(e.records.cols());
  // The null runs' mean and covariance; the records centred on that mean.
  const Eigen::VectorXd mu0 = e.null.rowwise().mean();
  const Eigen::MatrixXd centred_null = e.null.colwise() - mu0;
  Eigen::MatrixXd C0 = centred_null * centred_null.transpose() / static_cast<double>(e.null.cols() - 1);
  C0.diagonal().array() += 1e-9 * C0.trace() / static_cast<double>(J);
  const Eigen::MatrixXd z = e.records.colwise() - mu0;
  // W restricted to the tested estimates, and the test rows' responses to x.
  const Eigen::MatrixXd W_all = analyser.estimate_map();
  const std::vector<int>& x = analyser.estimate_x_columns();
  Eigen::MatrixXd W(J, W_all.cols());
  for (Eigen::Index k = 0; k < J; ++k)
    W.row(k) = W_all.row(std::find(x.begin(), x.end(), e.columns[static_cast<std::size_t>(k)]) - x.begin());
  const runs::BaseModel base = p.base_of(layout);
  const Eigen::Index nt = analyser.test_rows();
  const Eigen::Index nx = std::min<Eigen::Index>(base.H_x.cols(), uncertainty_slot::kDim);
  const Eigen::MatrixXd WH = W * base.H_x.topRows(nt).leftCols(nx);
  const EstimatePoint none = make_point(C0, Eigen::MatrixXd(J, 0));
  std::vector<int> half[2];
  for (int i = 0; i < n; ++i) half[i % 2].push_back(i);

  for (const Candidate& c : candidates) {
    const LayoutContext ctx{&p.layouts[static_cast<std::size_t>(layout)], &p.site, &base, {}};
    const std::vector<int> amps = c.amplitude_indices();
    std::vector<EstimatePoint> points;
    bool inside = true;
    for (int g = 0; g < c.grid_size() && inside; ++g) {
      std::vector<double> at = c.grid_point(g);
      const runs::Extension e0 = c.build(ctx, at);
      inside = acts_inside_priors(e0);
      if (!inside) break;
      Eigen::VectorXd dp(nx);
      for (Eigen::Index k = 0; k < nx; ++k) dp[k] = base.x_var[k] * (e0.x_var_scale[k] - 1.0) + e0.x_var_add[k];
      const Eigen::MatrixXd S = C0 + WH * dp.asDiagonal() * WH.transpose();
      Eigen::MatrixXd D(J, static_cast<Eigen::Index>(amps.size()));
      for (std::size_t i = 0; i < amps.size(); ++i) {
        std::vector<double> unit = at;
        unit[static_cast<std::size_t>(amps[i])] = 1.0;  // SI: the signature per unit amplitude
        const runs::Extension e1 = c.build(ctx, unit);
        D.col(static_cast<Eigen::Index>(i)) =
            e1.mean.size() ? Eigen::VectorXd(W * e1.mean.head(nt)) : Eigen::VectorXd::Zero(J);
      }
      points.push_back(make_point(S, std::move(D)));
    }
    if (!inside || points.empty()) continue;
    // 2-fold: the best grid point and amplitudes on one half, scored on the other.
    double gain = 0;
    for (int f = 0; f < 2; ++f) {
      const std::vector<int>& fit = half[f];
      const std::vector<int>& held = half[1 - f];
      double best = -std::numeric_limits<double>::infinity();
      std::size_t best_g = 0;
      Eigen::VectorXd best_a;
      for (std::size_t g = 0; g < points.size(); ++g) {
        const Eigen::VectorXd a = amplitudes(points[g], z, fit);
        const double ll = log_likelihood(points[g], a, z, fit);
        if (ll > best) best = ll, best_g = g, best_a = a;
      }
      gain += log_likelihood(points[best_g], best_a, z, held) - log_likelihood(none, Eigen::VectorXd(), z, held);
    }
    test.scores.push_back({c.name, gain});
  }
  std::sort(test.scores.begin(), test.scores.end(),
            [](const EstimateScore& a, const EstimateScore& b) { return a.heldout_gain > b.heldout_gain; });
  if (test.scores.empty() || test.scores.front().heldout_gain <= 0) return;
  test.named = test.scores.front().effect;
  if (test.scores.size() > 1 && test.scores[1].heldout_gain > 0 &&
      test.scores[0].heldout_gain - test.scores[1].heldout_gain < kClassNats) {
    test.named += "|" + test.scores[1].effect;
    test.told_apart_by = what_tells_apart(test.scores[0].effect, test.scores[1].effect);
  }
}

}  // namespace insmc::gap
