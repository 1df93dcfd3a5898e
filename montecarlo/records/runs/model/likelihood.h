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
#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <span>

#include "montecarlo/records/runs/model/gaussian_model.h"

namespace insmc::runs {

class LatticeLikelihood;

class RunLikelihood {
 public:
  /// Factorizes the model once; every run of its layout is then cheap.
  explicit RunLikelihood(const GaussianModel& model);
  /// The likelihood of the layout made of the rows `rows` (ascending) of a
  /// lattice's model (layout_union.h): M of those rows is the lattice's less
  /// the rows it lacks, so by the determinant lemma and Woodbury
  ///   log|M_ℓ| = log|M| + log|I − Gᵀ M⁻¹ G|,  M_ℓ⁻¹ = M⁻¹ + U C Uᵀ,
  /// U = M⁻¹ G, C = (I − Gᵀ U)⁻¹, g_m = s h_mᵀ/σ_m of each row m it lacks:
  /// O(causes² × k) once per layout instead of O(rows × causes²). Fitted
  /// anew on its rows where that would lose digits (as run_analysis.h).
  RunLikelihood(const LatticeLikelihood& lattice, std::span<const Eigen::Index> rows);

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
  // A layout cut from a lattice: b = Gᵀ r with G = W R⁻¹ of its rows, and
  // bᵀ M_ℓ⁻¹ b = bᵀ M⁻¹ b + (Uᵀ b)ᵀ C (Uᵀ b) through the lattice's factor.
  const LatticeLikelihood* lattice_ = nullptr;
  Eigen::MatrixXd weighted_;  // rows × d: W R⁻¹
  Eigen::MatrixXd U_, C_;     // d × k, k × k
};

/// A lattice model factorized once, for the layouts cut from it.
class LatticeLikelihood {
 public:
  explicit LatticeLikelihood(const GaussianModel& model);

 private:
  friend class RunLikelihood;
  GaussianModel model_;        // the lattice's, for a layout fitted anew
  Eigen::VectorXd mean_, inv_noise_;  // rows
  Eigen::MatrixXd W_;          // rows × active causes: H s
  Eigen::LLT<Eigen::MatrixXd> llt_;  // of M = I + Wᵀ R⁻¹ W
  double log_det_m_ = 0.0;
  bool factorized_ = false;    // M's Cholesky factor held (else every layout is fitted anew)
};

}  // namespace insmc::runs
