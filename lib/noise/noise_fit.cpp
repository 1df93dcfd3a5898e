#include "lib/noise/noise_fit.h"

#include "lib/noise/allan_covariance.h"

#include <Eigen/Dense>
#include <algorithm>
#include <boost/math/distributions/chi_squared.hpp>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>

namespace insmc::noise {

double NoiseModel::avar(double tau_s) const {
  double v = 0;
  for (NoiseTerm t : kAllNoiseTerms)
    if ((*this)[t] > 0) v += (*this)[t] * avar_shape(t, tau_s, correlation_time_s);
  return v;
}

PowerLaw NoiseModel::dominant_type(double tau_s) const {
  double best = -1;
  int alpha = 0;
  for (NoiseTerm t : kAllNoiseTerms) {
    const double v = (*this)[t] > 0 ? (*this)[t] * avar_shape(t, tau_s, correlation_time_s) : 0;
    if (v > best) best = v, alpha = power_law_alpha(t, tau_s, correlation_time_s);
  }
  return static_cast<PowerLaw>(alpha);
}

double NoiseModel::mean_difference_variance(double tau_s, double lag_s) const {
  double v = 0;
  for (NoiseTerm t : kAllNoiseTerms)
    if ((*this)[t] > 0) v += (*this)[t] * mean_difference_shape(t, tau_s, lag_s, correlation_time_s);
  return v;
}

namespace {

/// min ‖Ax − b‖ subject to x ≥ 0 (Lawson & Hanson 1974, algorithm NNLS).
Eigen::VectorXd nnls(const Eigen::MatrixXd& A, const Eigen::VectorXd& b) {
  const Eigen::Index n = A.cols();
  Eigen::VectorXd x = Eigen::VectorXd::Zero(n);
  std::vector<bool> passive(static_cast<std::size_t>(n), false);
  const double tol = 1e-12 * (A.norm() * b.norm() + 1e-300);
  for (int outer = 0; outer < 3 * n + 10; ++outer) {
    const Eigen::VectorXd w = A.transpose() * (b - A * x);
    Eigen::Index best = -1;
    for (Eigen::Index k = 0; k < n; ++k)
      if (!passive[static_cast<std::size_t>(k)] && w(k) > tol && (best < 0 || w(k) > w(best))) best = k;
    if (best < 0) break;
    passive[static_cast<std::size_t>(best)] = true;
    for (int inner = 0; inner < 3 * n + 10; ++inner) {
      std::vector<Eigen::Index> idx;
      for (Eigen::Index k = 0; k < n; ++k)
        if (passive[static_cast<std::size_t>(k)]) idx.push_back(k);
      Eigen::MatrixXd Ap(A.rows(), static_cast<Eigen::Index>(idx.size()));
      for (std::size_t i = 0; i < idx.size(); ++i) Ap.col(static_cast<Eigen::Index>(i)) = A.col(idx[i]);
      const Eigen::VectorXd zp = Ap.colPivHouseholderQr().solve(b);
      Eigen::VectorXd z = Eigen::VectorXd::Zero(n);
      for (std::size_t i = 0; i < idx.size(); ++i) z(idx[i]) = zp(static_cast<Eigen::Index>(i));
      bool feasible = true;
      for (Eigen::Index k : idx) feasible = feasible && z(k) > 0;
      if (feasible) {
        x = z;
        break;
      }
      double step = 1;
      for (Eigen::Index k : idx)
        if (z(k) <= 0) step = std::min(step, x(k) / (x(k) - z(k)));
      x += step * (z - x);
      for (Eigen::Index k : idx)
        if (x(k) <= 1e-300) passive[static_cast<std::size_t>(k)] = false, x(k) = 0;
    }
  }
  return x;
}

/// The pilot objective (N.2): levels independent, ν̂_j ~ ν_j χ²(d_j)/d_j.
struct Levels {
  std::vector<double> tau, nu_hat, edf;
};

double neg_log_likelihood(const Levels& L, const NoiseModel& m) {
  double s = 0;
  for (std::size_t j = 0; j < L.tau.size(); ++j) {
    const double nu = std::max(m.avar(L.tau[j]), 1e-300);
    s += L.edf[j] / 2 * (L.nu_hat[j] / nu + std::log(nu));  // (N.2)
  }
  return s;
}

/// The fit's objective (N.5): the relative residuals r_j = (ν̂_j − ν_j)/ν̃_j
/// weighted by the inverse of their covariance under the pilot model ν̃,
/// J = rᵀ S⁻¹ r = ‖L⁻¹ r‖² with S = L Lᵀ.
struct Weighted {
  std::vector<double> tau, nu_hat, pilot;
  Eigen::MatrixXd whiten;  ///< L⁻¹
  std::span<const AllanLevel> levels;  ///< the levels fitted (for a model's own covariance)
};

double objective(const Weighted& W, const NoiseModel& m) {
  Eigen::VectorXd r(static_cast<Eigen::Index>(W.tau.size()));
  for (std::size_t j = 0; j < W.tau.size(); ++j)
    r(static_cast<Eigen::Index>(j)) = (W.nu_hat[j] - m.avar(W.tau[j])) / W.pilot[j];
  return (W.whiten * r).squaredNorm();
}

struct Fixed {
  NoiseTerm term;
  double power;
};

/// min ‖M(Ap − b)‖ over p ≥ 0 with the columns scaled to unit norm first.
void solve_scaled(Eigen::MatrixXd A, const Eigen::VectorXd& b, const std::vector<NoiseTerm>& terms, NoiseModel& m) {
  const Eigen::Index K = A.cols();
  Eigen::VectorXd scale(K);
  for (Eigen::Index k = 0; k < K; ++k) {
    scale(k) = A.col(k).norm();
    if (scale(k) > 0) A.col(k) /= scale(k);
  }
  const Eigen::VectorXd y = K > 0 ? nnls(A, b) : Eigen::VectorXd();
  for (Eigen::Index k = 0; k < K; ++k) m[terms[static_cast<std::size_t>(k)]] = scale(k) > 0 ? y(k) / scale(k) : 0.0;
}

/// The powers of `terms` at a fixed T_c that minimise (N.5), with an
/// optional term held at a given power (profile).
NoiseModel fit_powers(const Weighted& W, const std::vector<NoiseTerm>& terms, double tc, std::optional<Fixed> fixed) {
  const auto J = static_cast<Eigen::Index>(W.tau.size()), K = static_cast<Eigen::Index>(terms.size());
  NoiseModel m;
  m.correlation_time_s = tc;
  if (fixed) m[fixed->term] = fixed->power;
  Eigen::MatrixXd A(J, K);
  Eigen::VectorXd b(J);
  for (Eigen::Index j = 0; j < J; ++j) {
    const auto ju = static_cast<std::size_t>(j);
    const double offset = fixed ? fixed->power * avar_shape(fixed->term, W.tau[ju], tc) : 0.0;
    for (Eigen::Index k = 0; k < K; ++k) A(j, k) = avar_shape(terms[static_cast<std::size_t>(k)], W.tau[ju], tc) / W.pilot[ju];
    b(j) = (W.nu_hat[ju] - offset) / W.pilot[ju];
  }
  solve_scaled(W.whiten * A, W.whiten * b, terms, m);
  return m;
}

/// The powers at a fixed T_c that minimise (N.2), by iteratively reweighted
/// non-negative least squares (the pilot fit).
NoiseModel fit_powers(const Levels& L, const std::vector<NoiseTerm>& terms, double tc, std::optional<Fixed> fixed) {
  const auto J = static_cast<Eigen::Index>(L.tau.size()), K = static_cast<Eigen::Index>(terms.size());
  NoiseModel m;
  m.correlation_time_s = tc;
  std::vector<double> nu_weight = L.nu_hat;
  NoiseModel best = m;
  double best_nll = std::numeric_limits<double>::infinity(), previous = best_nll;
  // The pilot only weights the fit below; 50 iterations reach its fixed
  // point on every recording tried, and bound the cost where none exists
  // (a recording no model fits: the reweighting then cycles).
  for (int iter = 0; iter < 50; ++iter) {
    Eigen::MatrixXd A(J, K);
    Eigen::VectorXd b(J);
    for (Eigen::Index j = 0; j < J; ++j) {
      const auto ju = static_cast<std::size_t>(j);
      const double s = std::sqrt(L.edf[ju] / 2) / std::max(nu_weight[ju], 1e-300);
      for (Eigen::Index k = 0; k < K; ++k) A(j, k) = s * avar_shape(terms[static_cast<std::size_t>(k)], L.tau[ju], tc);
      b(j) = s * L.nu_hat[ju];
    }
    NoiseModel next = m;
    solve_scaled(A, b, terms, next);
    const double nll = neg_log_likelihood(L, next);
    if (nll < best_nll) best_nll = nll, best = next;
    if (std::abs(nll - previous) <= 1e-11 * (std::abs(nll) + 1)) break;
    previous = nll;
    for (std::size_t j = 0; j < L.tau.size(); ++j) nu_weight[j] = std::max(next.avar(L.tau[j]), 1e-30 * L.nu_hat[j]);
  }
  (void)fixed;  // the pilot never holds a term
  return best;
}

double score(const Levels& L, const NoiseModel& m) { return 2 * neg_log_likelihood(L, m); }
double score(const Weighted& W, const NoiseModel& m) { return objective(W, m); }

bool has(const std::vector<NoiseTerm>& terms, NoiseTerm t) { return std::find(terms.begin(), terms.end(), t) != terms.end(); }

/// The range of T_c searched: the cluster times, up to half the longest.
/// Outside it a Gauss–Markov process is indistinguishable from a white rate
/// (T_c below) or a rate random walk (T_c above), which the fit has already.
std::pair<double, double> tc_range(const std::vector<double>& tau) { return {tau.front(), tau.back() / 2}; }

/// Best model over T_c (if the Gauss–Markov term is in `terms` or is the
/// fixed one), with an optional term held at a given power.
template <class Problem>
NoiseModel fit_terms(const Problem& P, const std::vector<NoiseTerm>& terms, std::optional<Fixed> fixed = std::nullopt) {
  if (!has(terms, NoiseTerm::kGaussMarkov) && !(fixed && fixed->term == NoiseTerm::kGaussMarkov))
    return fit_powers(P, terms, 0.0, fixed);
  const auto [lo, hi] = tc_range(P.tau);
  const int grid = 28;
  std::vector<double> ln_tc(grid), value(grid);
  std::vector<NoiseModel> models(grid);
  int best = 0;
  for (int i = 0; i < grid; ++i) {
    ln_tc[i] = std::log(lo) + (std::log(hi) - std::log(lo)) * i / (grid - 1);
    models[i] = fit_powers(P, terms, std::exp(ln_tc[i]), fixed);
    value[i] = score(P, models[i]);
    if (value[i] < value[best]) best = i;
  }
  // Golden-section refinement between the neighbours of the best grid point.
  double a = ln_tc[std::max(best - 1, 0)], b = ln_tc[std::min(best + 1, grid - 1)];
  const double r = (std::sqrt(5.0) - 1) / 2;
  NoiseModel best_model = models[best];
  double best_value = value[best];
  auto eval = [&](double x) {
    NoiseModel m = fit_powers(P, terms, std::exp(x), fixed);
    const double v = score(P, m);
    if (v < best_value) best_value = v, best_model = m;
    return v;
  };
  double c = b - r * (b - a), d = a + r * (b - a), fc = eval(c), fd = eval(d);
  for (int i = 0; i < 30; ++i) {
    if (fc < fd) b = d, d = c, fd = fc, c = b - r * (b - a), fc = eval(c);
    else a = c, c = d, fc = fd, d = a + r * (b - a), fd = eval(d);
  }
  return best_model;
}

double chi2_quantile(double df, double p) { return boost::math::quantile(boost::math::chi_squared(df), p); }

/// The parameters a model fits: its powers, and T_c with a Gauss–Markov term.
double parameters(const std::vector<NoiseTerm>& terms) {
  return static_cast<double>(terms.size()) + (has(terms, NoiseTerm::kGaussMarkov) ? 1.0 : 0.0);
}

/// Does the model pass the fit test? The pilot's (N.2) treats the levels as
/// independent and is no goodness-of-fit statistic: it never rules a
/// simplification out. (N.5) is, with χ²(levels − parameters).
bool passes(const Levels&, const NoiseModel&, const std::vector<NoiseTerm>&, double) { return true; }
/// The test is the one the fit is judged by at the end: J under the
/// candidate's own covariance. Under the pilot's weighting a model without
/// the pilot's long-τ term passes wrongly: the pilot's large variance there
/// makes any residual at long τ cheap (a Gauss–Markov model without the
/// random walk passed with J = 9.6 under a random-walk pilot and gave
/// J = 7,400 under its own covariance).
Weighted weighted_problem(std::span<const AllanLevel> levels, const NoiseModel& pilot);
/// A model with as many parameters as levels (no degree of freedom left)
/// cannot be tested, so it does not pass.
bool passes(const Weighted& W, const NoiseModel& m, const std::vector<NoiseTerm>& terms, double alpha) {
  const double dof = static_cast<double>(W.tau.size()) - parameters(terms);
  return dof >= 1 && objective(weighted_problem(W.levels, m), m) <= chi2_quantile(dof, 1 - alpha);
}

/// The simplifications of a term set tried by the backward elimination,
/// each with the parameters it removes: every term dropped (two parameters
/// for the Gauss–Markov term, one if a white rate or a random walk remains
/// to take its limit T_c → 0 or ∞), and the Gauss–Markov term replaced by
/// either limit (one parameter).
struct Simplification {
  std::vector<NoiseTerm> terms;
  NoiseTerm removed;
  double df;
};

std::vector<Simplification> simplifications(const std::vector<NoiseTerm>& selected, const std::vector<NoiseTerm>& allowed) {
  std::vector<Simplification> out;
  for (std::size_t i = 0; i < selected.size(); ++i) {
    std::vector<NoiseTerm> fewer = selected;
    fewer.erase(fewer.begin() + static_cast<std::ptrdiff_t>(i));
    double df = 1;
    if (selected[i] == NoiseTerm::kGaussMarkov) {
      df = has(fewer, NoiseTerm::kWhiteRate) || has(fewer, NoiseTerm::kRateRandomWalk) ? 1 : 2;
      for (NoiseTerm limit : {NoiseTerm::kWhiteRate, NoiseTerm::kRateRandomWalk})
        if (!has(fewer, limit) && has(allowed, limit)) {
          std::vector<NoiseTerm> swapped = fewer;
          swapped.push_back(limit);
          std::sort(swapped.begin(), swapped.end());
          out.push_back({swapped, NoiseTerm::kGaussMarkov, 1});
        }
    }
    if (!fewer.empty()) out.push_back({fewer, selected[i], df});
  }
  return out;
}

/// Backward elimination: take the simplification with the smallest margin
/// (rise of the score minus χ²_df at 1 − 2α) while that margin is negative.
/// The fit test (a model's own covariance, the costly part) is computed for
/// the candidates in order of margin until one passes, not for all of them.
template <class Problem>
NoiseModel select_terms(const Problem& P, std::vector<NoiseTerm>& selected, std::vector<TermFit>& dropped,
                        const NoiseFitOptions& options) {
  NoiseModel model = fit_terms(P, selected);
  double value = score(P, model);
  bool current_passes = passes(P, model, selected, options.selection_alpha);
  struct Tried {
    Simplification simplification;
    NoiseModel model;
    double stat, margin;
  };
  while (selected.size() > 1) {
    std::vector<Tried> tried;
    for (const Simplification& s : simplifications(selected, options.allowed)) {
      const NoiseModel m = fit_terms(P, s.terms);
      const double stat = std::max(0.0, score(P, m) - value);
      const double margin = stat - chi2_quantile(s.df, 1 - 2 * options.selection_alpha);
      if (margin < 0) tried.push_back({s, m, stat, margin});
    }
    std::stable_sort(tried.begin(), tried.end(), [](const Tried& a, const Tried& b) { return a.margin < b.margin; });
    // Under a weighting that no model of these terms passes yet, the fit
    // test cannot tell simplifications apart: the likelihood-ratio test alone.
    const auto best = std::find_if(tried.begin(), tried.end(), [&](const Tried& t) {
      return !current_passes || passes(P, t.model, t.simplification.terms, options.selection_alpha);
    });
    if (best == tried.end()) break;
    dropped.push_back({best->simplification.removed, 0, 0, 0, best->stat});
    selected = best->simplification.terms;
    model = best->model;
    value = score(P, model);
    if (!current_passes) current_passes = passes(P, model, selected, options.selection_alpha);
  }
  return model;
}

/// The weighted problem under a pilot model: S from (N.4), relative to ν̃.
Weighted weighted_problem(std::span<const AllanLevel> levels, const NoiseModel& pilot) {
  Weighted W;
  W.levels = levels;
  const double dt = levels.front().tau_s / static_cast<double>(levels.front().cluster);
  const Eigen::MatrixXd cov = allan_covariance(levels, dt, pilot);
  const auto J = static_cast<Eigen::Index>(levels.size());
  for (const AllanLevel& l : levels) {
    W.tau.push_back(l.tau_s);
    W.nu_hat.push_back(l.avar);
    W.pilot.push_back(std::max(pilot.avar(l.tau_s), 1e-300));
  }
  Eigen::MatrixXd S(J, J);
  for (Eigen::Index i = 0; i < J; ++i)
    for (Eigen::Index j = 0; j < J; ++j)
      S(i, j) = cov(i, j) / (W.pilot[static_cast<std::size_t>(i)] * W.pilot[static_cast<std::size_t>(j)]);
  // A tiny ridge keeps the factorization defined when two levels are almost
  // perfectly correlated (it changes no weight by more than 1e-9 relative).
  S.diagonal().array() += 1e-9 * S.diagonal().mean();
  const Eigen::LLT<Eigen::MatrixXd> llt(S);
  W.whiten = llt.matrixL().solve(Eigen::MatrixXd::Identity(J, J));
  return W;
}

/// The degrees of freedom that match a level's variance under the model,
/// 2ν²/Var ν̂, within [1, the level's windows]: no more independent squares
/// than second differences were summed. (Where the model's variance there is
/// almost nothing, as under a rate ramp alone, the ratio is any number: an
/// interval from 10³⁰ degrees of freedom would be no interval.)
double model_edf(const AllanLevel& level, const NoiseModel& m, double var) {
  const double nu = m.avar(level.tau_s);
  const double edf = var > 0 ? 2 * nu * nu / var : allan_edf(level, m.dominant_type(level.tau_s));
  return std::isfinite(edf) ? std::clamp(edf, 1.0, std::max(1.0, static_cast<double>(level.windows))) : 1.0;
}

/// Bisection on a monotone profile: the point between `inside` (profile
/// below the target) and `outside` where it crosses the target.
template <class F>
double crossing(F&& excess, double inside, double outside) {
  for (int i = 0; i < 60; ++i) {
    const double mid = (inside + outside) / 2;
    (excess(mid) <= 0 ? inside : outside) = mid;
  }
  return (inside + outside) / 2;
}

}  // namespace

namespace {

/// The fit over all the given levels (docs/noise.md §3), with its fit test.
NoiseFit fit_levels(std::span<const AllanLevel> levels, const NoiseFitOptions& options) {
  // Pilot: (N.2) with the degrees of freedom of each level's dominant noise
  // type, every allowed term (its model weights the fit below).
  Levels L;
  for (const AllanLevel& l : levels) {
    L.tau.push_back(l.tau_s), L.nu_hat.push_back(l.avar);
    L.edf.push_back(allan_edf(l, PowerLaw::kWhiteRate));
  }
  std::vector<NoiseTerm> selected = options.allowed;
  std::vector<TermFit> dropped;
  NoiseModel model = select_terms(L, selected, dropped, options);
  for (std::size_t j = 0; j < levels.size(); ++j) L.edf[j] = allan_edf(levels[j], model.dominant_type(L.tau[j]));
  selected = options.allowed;
  dropped.clear();
  model = select_terms(L, selected, dropped, options);
  // The fit: (N.5) weighted by the covariance (N.4) under the pilot, twice
  // (the second time under the first weighted fit).
  Weighted W;
  for (int pass = 0; pass < 2; ++pass) {
    W = weighted_problem(levels, model);
    selected = options.allowed;
    dropped.clear();
    model = select_terms(W, selected, dropped, options);
  }

  NoiseFit fit;
  fit.model = model;
  fit.dropped = dropped;
  fit.objective = objective(W, model);
  // The degrees of freedom that match each level's variance under the model: 2ν²/Var ν̂.
  const double dt = levels.front().tau_s / static_cast<double>(levels.front().cluster);
  const Eigen::MatrixXd cov = allan_covariance(levels, dt, model);
  for (std::size_t j = 0; j < levels.size(); ++j) {
    const double var = cov(static_cast<Eigen::Index>(j), static_cast<Eigen::Index>(j));
    fit.edf.push_back(model_edf(levels[j], model, var));
  }
  const double crit = chi2_quantile(1, options.confidence);
  const double tc = model.correlation_time_s;
  for (NoiseTerm t : kAllNoiseTerms) {
    if (!has(selected, t)) continue;
    TermFit tf;
    tf.term = t;
    tf.value_si = std::sqrt(model[t]);
    std::vector<NoiseTerm> others;
    for (NoiseTerm o : selected)
      if (o != t) others.push_back(o);
    tf.drop_statistic = others.empty() ? std::numeric_limits<double>::infinity()
                                       : std::max(0.0, objective(W, fit_terms(W, others)) - fit.objective);
    // Profile in the coefficient c = √p, the other powers refitted.
    // For the Gauss–Markov σ, T_c is refitted too (σ and T_c are strongly correlated).
    auto excess = [&](double c) {
      const NoiseModel m = t == NoiseTerm::kGaussMarkov ? fit_terms(W, others, Fixed{t, c * c})
                                                        : fit_powers(W, others, tc, Fixed{t, c * c});
      return objective(W, m) - fit.objective - crit;
    };
    const double c0 = tf.value_si;
    double hi = c0 * 2;
    for (int i = 0; i < 60 && excess(hi) <= 0; ++i) hi *= 2;
    tf.upper_si = crossing(excess, c0, hi);
    tf.lower_si = excess(0.0) <= 0 ? 0.0 : crossing(excess, c0, 0.0);
    fit.terms.push_back(tf);
  }
  if (has(selected, NoiseTerm::kGaussMarkov)) {
    const auto [lo, hi] = tc_range(W.tau);
    auto excess = [&](double ln_tc) {
      return objective(W, fit_powers(W, selected, std::exp(ln_tc), std::nullopt)) - fit.objective - crit;
    };
    const double x0 = std::log(tc);
    fit.correlation_time_lower_s = excess(std::log(lo)) <= 0 ? lo : std::exp(crossing(excess, x0, std::log(lo)));
    fit.correlation_time_upper_s = excess(std::log(hi)) <= 0 ? hi : std::exp(crossing(excess, x0, std::log(hi)));
  }
  // The fit test under the model's own covariance.
  const Weighted own = weighted_problem(levels, model);
  fit.fit_statistic = objective(own, model);
  fit.fit_dof = static_cast<double>(levels.size()) - parameters(selected);
  // A model without a degree of freedom left, or whose own covariance is
  // singular (a rate ramp alone has no variance: S = 0), cannot be tested,
  // so it does not pass.
  const bool testable = std::isfinite(fit.fit_statistic) && fit.fit_dof >= 1;
  fit.fit_p_value = testable ? boost::math::cdf(boost::math::complement(boost::math::chi_squared(fit.fit_dof),
                                                                        fit.fit_statistic))
                             : 0.0;
  fit.fits = fit.fit_p_value >= options.selection_alpha;
  return fit;
}

}  // namespace

NoiseFit fit_noise(std::span<const AllanLevel> levels, const NoiseFitOptions& options) {
  if (levels.size() < 2) throw std::invalid_argument("fit_noise: at least two Allan levels are needed");
  // A channel that never changes (a constant or synthetic output): no noise
  // to fit, every term absent.
  if (std::none_of(levels.begin(), levels.end(), [](const AllanLevel& l) { return l.avar > 0; })) {
    NoiseFit none;
    none.edf.assign(levels.size(), 1.0);
    return none;
  }
  NoiseFit fit = fit_levels(levels, options);
  // Leave out the shortest levels one at a time until a model passes.
  for (std::size_t first = 1; !fit.fits && levels.size() - first >= kMinFitLevels; ++first) {
    NoiseFit trimmed = fit_levels(levels.subspan(first), options);
    trimmed.first_level = first;
    const bool done = trimmed.fits;
    if (done) fit = std::move(trimmed);
    if (done) break;
  }
  if (fit.first_level > 0) {
    // The degrees of freedom of the levels left out, under the model (the
    // data's interval there), in front of those of the fitted levels.
    const double dt = levels.front().tau_s / static_cast<double>(levels.front().cluster);
    const Eigen::MatrixXd cov = allan_covariance(levels.first(fit.first_level), dt, fit.model);
    std::vector<double> edf;
    for (std::size_t j = 0; j < fit.first_level; ++j) {
      const double var = cov(static_cast<Eigen::Index>(j), static_cast<Eigen::Index>(j));
      edf.push_back(model_edf(levels[j], fit.model, var));
    }
    fit.edf.insert(fit.edf.begin(), edf.begin(), edf.end());
  }
  return fit;
}

}  // namespace insmc::noise
