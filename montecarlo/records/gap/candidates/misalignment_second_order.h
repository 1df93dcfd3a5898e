#pragma once
/// A misalignment's rotation to second order, for the candidates that widen
/// the switch-over misalignment (alignment_transient.cpp reaches tens of
/// mrad in azimuth; switch_transient.cpp takes it alike, so that neither is
/// favoured by a term only one of them has).
///
/// The platform turned by φ measures R f = f + [φ×] f + ½ [φ×]² f + … of
/// the specific force at rest f^{a'}(t) (3.24); the run model (3.22)–(3.24)
/// holds the first term through ζ_r. With an azimuth of tens of mrad the
/// second is not small: gravity turns in the space-stabilized platform with
/// the earth, and ½ φ_z² of its horizontal part grows through the
/// navigation, of one sign in every run (a mean the runs share).
///
/// With φ = D z, z standard normal (D: the 1σ per axis),
///   ½ [φ×]² f = ½ (φ (φ·f) − |φ|² f) = Σ_i z_i² B_ii + Σ_{i<j} z_i z_j B_ij,
///   B_ii = ½ D_i² (e_i f_i − f),   B_ij = ½ D_i D_j (e_i f_j + e_j f_i).
/// Its mean is Σ_i B_ii; the rest are six terms uncorrelated with one
/// another and with the first order (odd moments of z vanish), of variance
/// 2 B_ii² and B_ij²: a Gaussian model with the rotation's first and second
/// moments.
#include <Eigen/Dense>
#include <array>

#include "montecarlo/records/gap/candidates/candidates.h"
#include "montecarlo/records/runs/model/gaussian_model.h"

namespace insmc::gap::candidates {

/// (i, j) of the six terms: the three squares, then the three products.
inline constexpr std::array<std::array<int, 2>, 6> kSecondOrderTerms{{{0, 0}, {1, 1}, {2, 2}, {0, 1}, {0, 2}, {1, 2}}};

/// The terms at D = 1 (3 × 6, columns in kSecondOrderTerms' order): ½ (e_i f_j
/// + e_j f_i), less ½ f where i = j.
Eigen::Matrix<double, 3, 6> second_order_unit_terms(const Eigen::Vector3d& f);

/// Per term: its weight in the mean (D_i² for a square, 0 for a product)
/// and its variance (2 D_i⁴ for a square, D_i² D_j² for a product).
struct SecondOrderWeights {
  Eigen::Matrix<double, 6, 1> mean;
  Eigen::Matrix<double, 6, 1> variance;
};
SecondOrderWeights second_order_weights(const Eigen::Vector3d& sigma_rad);

/// Adds to `e` the second order of a switch-over misalignment of 1σ
/// `sigma_rad` per axis: its mean, the same in every run, and six columns of
/// its spread, through the run's response (the unit terms' responses are
/// kept in the layout's cache for every grid point). The first order is the
/// caller's (ζ_r's priors); the columns are marked higher-order.
void add_misalignment_second_order(const LayoutContext& ctx, const Eigen::Vector3d& sigma_rad, runs::Extension& e);

}  // namespace insmc::gap::candidates
