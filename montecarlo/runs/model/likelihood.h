#pragma once
/// The exact Gaussian log-likelihood of one run's rows (test and navigation
/// alike) under a GaussianModel (gaussian_model.h):
///   y = μ + H c + e,  c ~ N(0, P = diag(prior_var)),  e ~ N(0, R = diag(noise_var)),
///   log p(y) = −½ [ n log 2π + log|S| + (y − μ)ᵀ S⁻¹ (y − μ) ],  S = H P Hᵀ + R.
/// The gap metric (docs/gap-method.md §2) uses second moments only; the likelihood
/// is what a candidate's parameters are fitted by without grid edges
/// (likelihood_fit.h). R is the fit weights, noise_var, model-error floor
/// included (docs/gap-method.md §1): the floor stands for what the linear level does
/// not promise, and without it the likelihood would chase sub-metre detail.
///
/// S is never formed: with s = √prior (causes of prior 0 dropped) and
/// M = I + s Hᵀ R⁻¹ H s, the determinant lemma and Woodbury give
///   log|S| = Σ log R_i + log|M|,
///   (y−μ)ᵀ S⁻¹ (y−μ) = rᵀ R⁻¹ r − bᵀ M⁻¹ b,  r = y − μ, b = s Hᵀ R⁻¹ r,
/// O(n d²) once per model and O(n d) per run. The prior scaling keeps M
/// well conditioned across causes of very different units (as in
/// run_analysis.cpp).
#include <Eigen/Core>

#include "montecarlo/runs/model/gaussian_model.h"

namespace insmc::runs {

class RunLikelihood {
 public:
  /// Factorizes the model once; every run of its layout is then cheap.
  explicit RunLikelihood(const GaussianModel& model);

  /// log p(y) of one run's values y (layout order; the model mean is
  /// subtracted here).
  double log_likelihood(const Eigen::VectorXd& y) const;

  /// log|S|, and the number of rows n: E[−2 log p] = n log 2π + log|S| + n.
  double log_det() const { return log_det_; }
  Eigen::Index rows() const { return mean_.size(); }

 private:
  Eigen::VectorXd mean_;       // rows
  Eigen::VectorXd inv_noise_;  // rows: R⁻¹
  /// d × rows: T with ‖T r‖² = bᵀ M⁻¹ b (L⁻¹ s Hᵀ R⁻¹ from M = L Lᵀ).
  Eigen::MatrixXd whiten_;
  double log_det_ = 0.0;
};

}  // namespace insmc::runs
