#pragma once
/// The report's closed-form position error in the a' frame, per unit of
/// each term, for the navigation mode on a stationary base (§3.3, §3.4):
///   (3.27)  the Laplace solution of (3.25), terms in (ω_ie/ω_s)^n, n ≥ 4, dropped;
///   (3.28)  (3.27) with the (1 + ω_ie²/ω_s²) factors set to 1 and small terms dropped;
///   (3.29)  the short-run form (t ≤ 1.5 h) with δV(0), U2..U5.
/// Each form is δr(t) = a_r(t) δr(0) + a_v(t) δV(0) + r0 Σ_j h_j(t) K_j
/// (or the U-matrices), so the coefficient functions are given separately and
/// the maps are assembled in paper_model.h.
#include <array>

#include "lib/common/model_options.h"

namespace insmc {

/// Scalar coefficient functions of a closed form at time t [s].
struct ClosedFormCoefficients {
  double initial_position;      ///< multiplies δr(0)^{a'}
  double initial_velocity_s;    ///< multiplies δV(0)^{a'} [s]
  std::array<double, 11> k;     ///< multiply r0 K_1..K_11 (dimensionless)
};

/// Which reading of (3.27) to use.
enum class Form327 {
  kPrinted,    ///< as transcribed, transcription slips fixed (errata.md#transcription-slips)
  kCorrected,  ///< K6 terms re-derived (errata.md#3-27): the printed
               ///< ε(K6 − K7) sin φ and −(ω_ie/ω_s)³K6(φ − sin φ) read
               ///< −ε(3K6 + K7) sin φ and −εK6(φ − sin φ)
};

/// (3.27): the Laplace solution of (3.25), terms in (ω_ie/ω_s)^n, n ≥ 4, dropped.
ClosedFormCoefficients closed_form_3_27(double t_s, const ModelOptions& options,
                                        Form327 form = Form327::kPrinted);

/// (3.28).
ClosedFormCoefficients closed_form_3_28(double t_s, const ModelOptions& options);

/// The time functions of (3.29), multiplying δr(0), δV(0), r0 U2, r0 U3,
/// r0 U4, r0 U5:
///   1, sin(ω_s t)/ω_s, 1 − cos ω_s t, (ω_ie/ω_s)(ω_s t − sin ω_s t),
///   (ω_ie/ω_s)²[½ω_s²t² − (1 − cos ω_s t)], (ω_ie t)³/6.
struct ShortRunFunctions {
  double initial_position;
  double initial_velocity_s;
  double u2, u3, u4, u5;
};
ShortRunFunctions short_run_functions_3_29(double t_s, const ModelOptions& options);

/// The same functions with the U5 term taken from (3.30) in full:
/// (ω_ie/ω_s)³[(ω_s t)³/6 − (ω_s t − sin ω_s t)] (the report drops the second part).
double u5_function_3_30(double t_s, const ModelOptions& options);

}  // namespace insmc
