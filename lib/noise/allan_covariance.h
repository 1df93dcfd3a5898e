#pragma once
/// The covariance of overlapping Allan variance estimates at several cluster
/// times under a Gaussian noise model, the weight matrix of the fit
/// (docs/noise.md §3, as in the generalized method of wavelet moments).
///
/// With Δ_a(k) = θ_{k+2a} − 2θ_{k+a} + θ_k, the second differences are
/// Gaussian and Cov(Δ_a(k)², Δ_b(l)²) = 2 C_ab(k−l)², where
///   C_ab(h) = −½ Σ_{i,j} c_i c_j D((h + i a − j b) τ0),  c = (1, −2, 1)        (N.3)
/// follows from the model's structure function D (lib/noise/noise_terms.h;
/// the terms of degree ≤ 2 cancel). So, per segment,
///   Cov(ν̂_a, ν̂_b) = Σ_h n_ab(h) 2 C_ab(h)² / (4 τ_a² τ_b² N_a N_b)          (N.4)
/// with n_ab(h) the number of window pairs at lag h; segments are independent.
/// A rate ramp R adds 4 μ_a μ_b C_ab(h) to each term (μ_a = R τ_a², the mean
/// of Δ_a).
/// The sum runs over the lags where C_ab is not negligible: every whole lag up
/// to 4001 of them, beyond by the trapezoid rule on ≥ 4001 points (D tabulated).
#include <Eigen/Dense>
#include <span>

#include "lib/noise/allan_variance.h"

namespace insmc::noise {

struct NoiseModel;

/// Cov(ν̂_a, ν̂_b) for every pair of levels (all from one series with
/// spacing dt_s) under `model`.
Eigen::MatrixXd allan_covariance(std::span<const AllanLevel> levels, double dt_s, const NoiseModel& model);

}  // namespace insmc::noise
