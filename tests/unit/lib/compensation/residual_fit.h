#pragma once
// Shared by the compensation tests: the report's time functions of (3.29)
// on a scheme's clock, the least-squares projection of a scheme's position
// maps onto them, and the perturbations of the extended vector z
// (lib/compensation/extended_vector.h) one at a time.
//
// A perturbation p is a column of z-layout:
//  * p < uncertainty_slot::kDim: one uncertainty x_p, with every estimate and measurement
//    slot equal to what it estimates at the paper level (Û2 = U2 (3.29b),
//    Û3 = U3 (3.29c), Δf̂(T) = g{A1 + U3 ω_ie T + U4 ½ω_ie²T²} (5.10),
//    ω_c (5.14) and Δf_m (5.19) of the simplified steady state): the part
//    of the residual that is not an estimation error. For the per-alignment
//    slots this is the value of the test run, the report's ( )_p.
//  * p ≥ uncertainty_slot::kDim: one slot of z alone, in the report's units: the fresh
//    draws of the realignment, ( )_n; ε2 = Û2 − U2 and ε3 = Û3 − U3 (4.8b, c)
//    (also ε3 of the accelerometer slope (5.12), which 5.3 uses); E of (5.10)
//    (the slot holds g E); ε4 of (5.15) (the slot holds ω_ie ε4); ε5 of (5.19)
//    (the slot holds g ε5); ε_ṙ(T) of (5.8c) (the velocity the reset gets wrong).
#include <Eigen/Core>
#include <Eigen/QR>
#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "lib/alignment/alignment.h"
#include "lib/compensation/compensation_maps.h"
#include "lib/preflight/observables.h"
#include "lib/propagation/paper_model.h"
#include "lib/uncertainty/catalogue.h"
#include "lib/units/units.h"

namespace insmc::testing {

/// The report's time functions (3.29), in this order, on the scheme's clock:
///   δr(0): 1;  δV(0): sin(ω_s t)/ω_s;  U2: r0(1 − cos ω_s t);
///   U3: r0(ω_ie/ω_s)(ω_s t − sin ω_s t);  U4: r0(ω_ie/ω_s)²[½ω_s²t² − (1 − cos ω_s t)];
///   U5: r0 ω_ie³t³/6.
/// A coefficient is in m per unit (δr(0)), m/s per unit (δV(0)) or
/// dimensionless per unit (the U's).
enum Fn { kConst, kVel, kU2, kU3, kU4, kU5 };
inline constexpr int kFns = 6;
inline constexpr const char* kFnNames[kFns] = {"δr(0)", "δV(0)", "U2", "U3", "U4", "U5"};

inline double time_function(int fn, double t, const ModelOptions& m) {
  const double ws = m.schuler_radps(), w = m.earth_rate_radps, r0 = m.radius_m, x = ws * t, q = w / ws;
  switch (fn) {
    case kConst:
      return 1.0;
    case kVel:
      return std::sin(x) / ws;
    case kU2:
      return r0 * (1 - std::cos(x));
    case kU3:
      return r0 * q * (x - std::sin(x));
    case kU4:
      return r0 * q * q * (0.5 * x * x - (1 - std::cos(x)));
    default:
      return r0 * std::pow(w * t, 3) / 6;
  }
}

/// 1..90 min each minute on the scheme's clock: the report's 1.5 h.
inline std::vector<double> fit_times_s() {
  std::vector<double> t;
  for (int m = 1; m <= 90; ++m) t.push_back(60.0 * m);
  return t;
}

/// max over the fit times of |time function| (to turn a coefficient into ft).
inline double time_function_max(int fn, const ModelOptions& m) {
  double worst = 0;
  for (double t : fit_times_s()) worst = std::max(worst, std::abs(time_function(fn, t, m)));
  return worst;
}

/// Coefficient maps per time function: 3 × z_slot::kDim, column p = per unit of perturbation p.
using Coefficients = std::array<ExtendedMap, kFns>;

inline Coefficients zero_coefficients() {
  Coefficients c;
  for (auto& m : c) m.setZero();
  return c;
}

struct FitResult {
  Coefficients c;
  /// Per perturbation: max over axes and times of |δr − fitted δr| [m per
  /// unit]: how far the maps are from the span of the six time functions.
  Eigen::VectorXd worst_residual_m;
};

/// Projects δr(t_n) = M(t_n) P onto the time functions by least squares
/// (QR of the column-scaled design matrix, the columns span ten orders of
/// magnitude).
inline FitResult fit_time_functions(const std::vector<ExtendedMap>& maps, const std::vector<double>& times,
                                    const Eigen::MatrixXd& perturbations, const ModelOptions& m) {
  const Eigen::Index n = static_cast<Eigen::Index>(times.size());
  Eigen::MatrixXd b(n, kFns);
  for (Eigen::Index i = 0; i < n; ++i)
    for (int k = 0; k < kFns; ++k) b(i, k) = time_function(k, times[static_cast<size_t>(i)], m);
  const Eigen::VectorXd norms = b.colwise().norm().transpose();
  const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(b * norms.cwiseInverse().asDiagonal());
  FitResult out;
  out.c = zero_coefficients();
  out.worst_residual_m = Eigen::VectorXd::Zero(perturbations.cols());
  for (int axis = 0; axis < 3; ++axis) {
    Eigen::MatrixXd y(n, perturbations.cols());
    for (Eigen::Index i = 0; i < n; ++i) y.row(i) = maps[static_cast<size_t>(i)].row(axis) * perturbations;
    const Eigen::MatrixXd c = norms.cwiseInverse().asDiagonal() * qr.solve(y);
    for (int k = 0; k < kFns; ++k) out.c[k].row(axis) = c.row(k);
    out.worst_residual_m = out.worst_residual_m.cwiseMax((b * c - y).cwiseAbs().colwise().maxCoeff().transpose());
  }
  return out;
}

/// Report-unit scale of each z slot (see the header comment).
inline double slot_scale(int p, const ModelOptions& m) {
  if (p >= z_slot::kDfT && p < z_slot::kDfT + 3) return m.gravity_mps2;                              // g E
  if (p >= z_slot::kTorquerCommands && p < z_slot::kTorquerCommands + 3) return m.earth_rate_radps;  // ω_ie ε4
  if (p >= z_slot::kAlignAccel && p < z_slot::kAlignAccel + 3) return m.gravity_mps2;                // g ε5
  return 1.0;
}

/// The perturbations, one per column (z_slot::kDim × z_slot::kDim), at the paper level.
inline Eigen::MatrixXd perturbations(System system, const ModelOptions& m, const TestRunOptions& test) {
  const ShortRunMatrices sr = paper_short_run_matrices(system, m);
  const double g = m.gravity_mps2, w = m.earth_rate_radps, T = test.duration_s;
  const Sensitivity3 steady = simplified_steady_state_misalignment(system, m);
  Eigen::MatrixXd p = Eigen::MatrixXd::Zero(z_slot::kDim, z_slot::kDim);
  p.block(z_slot::kX, 0, uncertainty_slot::kDim, uncertainty_slot::kDim).setIdentity();
  p.block(z_slot::kU2, 0, 3, uncertainty_slot::kDim) = sr.u2;
  p.block(z_slot::kU3, 0, 3, uncertainty_slot::kDim) = sr.u3;
  p.block(z_slot::kU3Accel, 0, 3, uncertainty_slot::kDim) = sr.u3;
  p.block(z_slot::kDfT, 0, 3, uncertainty_slot::kDim) = g * (paper_a1(sr, m) + w * T * sr.u3 + 0.5 * w * w * T * T * sr.u4);
  p.block(z_slot::kTorquerCommands, 0, 3, uncertainty_slot::kDim) = torquer_commands(steady, m);
  p.block(z_slot::kAlignAccel, 0, 3, uncertainty_slot::kDim) = alignment_accelerometer_outputs(steady, m);
  for (int s = uncertainty_slot::kDim; s < z_slot::kDim; ++s) p(s, s) = slot_scale(s, m);
  return p;
}

/// Size of each perturbation for the tolerance rules (a "term" is a
/// coefficient times this): x at its Table 3.1 bound; the fresh draws at the
/// bound of their catalogue slot; ε2, E, ε5 at the A1 row and ε3 at the U3
/// row of Table 4.3 (4.6) for the test duration (§4.3: "the estimation
/// errors ... could be at least of the same order of magnitude as the
/// figures given in Table 4.3, rows 1 and 2"; §5.4.2 says the same for the
/// accelerometer outputs); ε4 at 10⁻⁴ (the unit Table 5.2 prints ε4 in);
/// ε_ṙ(T) at the (u)V bound (§4.3: the velocity uncertainty is the wiggle).
inline double magnitude(int p, const ModelOptions& m, const TestRunOptions& test) {
  const UncertaintyVector bound = default_bounds();
  if (p < uncertainty_slot::kDim) return bound[p];
  for (const RealignedSlot& r : kRealignedSlots)
    if (r.z_index == p) return bound[r.x_index];
  const ResolutionLimits lim = pulse_resolution_limits(0.1 * kFtpsToMps, test.duration_s, m);
  auto in = [p](int first) { return p >= first && p < first + 3; };
  if (in(z_slot::kU2) || in(z_slot::kDfT) || in(z_slot::kAlignAccel)) return lim.a1;
  if (in(z_slot::kU3) || in(z_slot::kU3Accel)) return lim.u3;
  if (in(z_slot::kTorquerCommands)) return 1e-4;
  return bound[uncertainty_slot::kInitialVelocity];  // ε_ṙ(T)
}

/// A readable name of perturbation p.
inline std::string perturbation_name(int p) {
  if (p < uncertainty_slot::kDim) return std::string(catalogue()[p].name);
  static const char* axes = "xyz";
  auto slot = [&](const char* what, int first) { return std::string(what) + axes[p - first]; };
  if (p < z_slot::kRealignBias) return slot("(zeta_r)_n ", z_slot::kRealignZeta);
  if (p < z_slot::kRealignVelocity) return slot("(df_r)_n ", z_slot::kRealignBias);
  if (p < z_slot::kU2) return slot("((u)V)_n ", z_slot::kRealignVelocity);
  if (p < z_slot::kU3) return slot("eps2", z_slot::kU2);
  if (p < z_slot::kU3Accel) return slot("eps3", z_slot::kU3);
  if (p < z_slot::kDfT) return slot("eps3(accel)", z_slot::kU3Accel);
  if (p < z_slot::kTorquerCommands) return slot("E", z_slot::kDfT);
  if (p < z_slot::kAlignAccel) return slot("eps4", z_slot::kTorquerCommands);
  if (p < z_slot::kWiggleAtT) return slot("eps5", z_slot::kAlignAccel);
  return slot("eps_rdot(T)", z_slot::kWiggleAtT);
}

/// The scheme's residual coefficients at the paper level for test run `test`,
/// with the printed or the corrected closed forms (compensation_maps.h).
inline FitResult scheme_coefficients(Scheme scheme, System system, const ModelOptions& m, const TestRunOptions& test,
                                     SchemeForms forms) {
  const std::vector<double> times = fit_times_s();
  const SchemeMaps maps = scheme_position_maps(scheme, system, Fidelity::kPaper, m, test, times, forms);
  return fit_time_functions(maps.position, times, perturbations(system, m, test), m);
}

}  // namespace insmc::testing
