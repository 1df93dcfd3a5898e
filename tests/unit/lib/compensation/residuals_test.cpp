// The residual coefficient matrices of chapter 5, derived from the
// compensated model (scheme_position_maps at the `paper` level, which
// propagates the model through the injection points of fig. 5.1 and never
// uses a printed residual formula) and compared term by term with the
// report's printed matrices, transcription slips fixed
// (tables/notes/errata.md#transcription-slips):
//   5.1.1 (5.4), (5.4a, b);  5.1.2 (5.7), (5.7a–d);  combined (end of 5.1.2);
//   5.2 (5.9a, b);  5.3 (5.11b);  5.4 (5.20), (5.17a–c);  none (3.29).
// Method: perturb one uncertainty (with every estimate equal to what it
// estimates) or one estimate/measurement slot of z at a time
// (residual_fit.h), evaluate δr^{a'}(t) for t = 1..90 min on the scheme's
// clock, and project it by least squares on the report's six time
// functions. At the paper level the maps lie in their span exactly, so the
// projection gives the coefficients themselves (asserted).
// Tolerances come from what each printed form says it neglects (Neglect
// below), applied to each term: a coefficient difference times the size of
// its perturbation (residual_fit.h: magnitude()). Where the printed formula
// is wrong, the test adds the derived correction (errata(), each entry
// citing tables/notes/errata.md), asserts that it is needed (the printed
// term alone is outside the tolerance) and that with it the corrected closed
// forms (SchemeForms::kCorrected) agree; the paper level itself
// (SchemeForms::kPrinted) must match the printed forms without the errata
// of (5.9), (5.11b) and (5.20)'s δg (it means every printed form):
//   errata.md#5-9   (5.9), (5.11b): the U5 term restarts at the reset;
//   errata.md#5-20  (5.20): ε5 and δg with the wrong sign;
//   errata.md#5-17b (5.17b): cos L0 for sin L0 (shown at L0 = 10°);
//   errata.md#5-7   (5.7d): one neglected term 6% above the stated cut.
// The printed forms are typed here from the report (struct Report),
// independently of lib/propagation; the ideal estimates use the library's
// paper-level U2, U3 (what Û2, Û3 estimate at that level).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <string>

#include "lib/propagation/position_maps.h"
#include "tests/unit/lib/compensation/residual_fit.h"

namespace insmc {
namespace {

using testing::Coefficients;
using testing::kConst;
using testing::kFnNames;
using testing::kFns;
using testing::kU2;
using testing::kU3;
using testing::kU4;
using testing::kU5;
using testing::kVel;

using ZRow = Eigen::Matrix<double, 1, z_slot::kDim>;

/// The row picking `scale` times slot `index` of the perturbation space.
ZRow e(int index, double scale = 1.0) {
  ZRow r = ZRow::Zero();
  r[index] = scale;
  return r;
}
ExtendedMap rows(const ZRow& x, const ZRow& y, const ZRow& z) {
  ExtendedMap m;
  m << x, y, z;
  return m;
}
const ZRow kZero = ZRow::Zero();

// ------------------------------------------------------------ the printed forms

/// Constants and the pieces of (3.22), (3.23), (3.29b–e) typed from the
/// report (independently of lib/propagation), with the per-alignment slots
/// of the current alignment `n` (fresh draws after a realignment) or of the
/// test run `p`.
struct Report {
  Report(System system, const ModelOptions& m, const TestRunOptions& t)
      : sys1(system == System::kTheodolite),
        g(m.gravity_mps2),
        w(m.earth_rate_radps),
        r0(m.radius_m),
        ws(m.schuler_radps()),
        T(t.duration_s),
        s(std::sin(m.latitude_rad)),
        c(std::cos(m.latitude_rad)),
        tn(std::tan(m.latitude_rad)),
        f_inv(1.0 / (m.leveling_gain_ratio * m.earth_rate_radps)) {}
  bool sys1;
  double g, w, r0, ws, T, s, c, tn, f_inv;

  // Slots of the per-alignment quantities, of the test run (p) or fresh (n).
  int zr(int k, bool fresh) const { return (fresh ? z_slot::kRealignZeta : uncertainty_slot::kMisalignAlign) + k; }
  int fr(int k, bool fresh) const { return (fresh ? z_slot::kRealignBias : uncertainty_slot::kBiasChangeAlign) + k; }
  int uv(int k, bool fresh) const { return (fresh ? z_slot::kRealignVelocity : uncertainty_slot::kInitialVelocity) + k; }
  ZRow zeta(int k, bool fresh) const { return e(uncertainty_slot::kMisalignConst + k) + e(zr(k, fresh)); }  // ζ = ζ_c + ζ_r
  ZRow dfc(int k, bool fresh) const { return e(uncertainty_slot::kBiasChangeConst + k, 1 / g) + e(fr(k, fresh), 1 / g); }  // ∂f/g
  ZRow drift(int k, double scale) const { return e(uncertainty_slot::kGyroDrift + k, scale / w); }   // ω_dok scale/ω_ie
  ZRow muy(int k, double scale) const { return e(uncertainty_slot::kGyroMuyDrift + k, scale / w); }  // g·MUY_k scale/ω_ie
  ZRow bias(int k, double scale) const { return e(uncertainty_slot::kAccelBias + k, scale / g); }    // δf_k scale/g
  /// ψ_ωz (2.17c): ≈ 0 for system 1 as (3.29c) prints it; −ω_doy/(ω_ie cos L0) for system 2.
  ZRow psi_wz() const { return sys1 ? kZero : drift(1, -1 / c); }

  ExtendedMap dr0() const { return rows(e(uncertainty_slot::kLatitudeError, r0), kZero, e(uncertainty_slot::kAltitudeError, -1)); }  // (3.22)
  /// (3.23) as printed (errata.md#3-23 kept at the paper level).
  ExtendedMap dv0(bool fresh) const {
    return rows(e(uv(0, fresh)), e(uv(1, fresh)) + e(uncertainty_slot::kLatitudeError, 2 * r0 * w * s) + e(uncertainty_slot::kAltitudeError, w * c),
                e(uv(2, fresh)));
  }
  /// (3.29b) with ψ_ωx,y = ω_dox,y/F(0) for system 1, 0 for system 2.
  ExtendedMap u2(bool fresh) const {
    const double f = sys1 ? f_inv : 0.0;
    return rows(dfc(0, fresh) + e(uncertainty_slot::kGyroDrift + 1, f) + zeta(1, fresh),
                dfc(1, fresh) - e(uncertainty_slot::kGyroDrift + 0, f) - zeta(0, fresh),
                bias(2, 1) - e(uncertainty_slot::kAccelScale + 2) + e(uncertainty_slot::kAltitudeError, -2 / r0));
  }
  /// (3.29c): U3x = cos L0 (ψ_fz + ψ_ωz + ζ'_z) + ω_doy/ω_ie with ψ_fz = (u)ψ,
  /// ζ'_z = ζ_z (1); ψ_fz = −δf_y/g tan L0, ζ'_z = ζ_z − ζ_x tan L0 (2).
  ExtendedMap u3(bool fresh) const {
    const ZRow psi_fz = sys1 ? e(uncertainty_slot::kTheodolite) : bias(1, -tn);
    const ZRow zeta_pz = sys1 ? zeta(2, fresh) : ZRow(zeta(2, fresh) - tn * zeta(0, fresh));
    return rows(c * (psi_fz + psi_wz() + zeta_pz) + drift(1, 1), drift(0, -1), -c * (bias(1, 1) + zeta(0, fresh)));
  }
  /// (3.29d): (1/ω_ie)[2ω_doz cos L0 + gMUY_y; −ω_ie ψ_ωz sin L0 cos L0 − gMUY_x; −2ω_dox cos L0].
  ExtendedMap u4() const { return rows(drift(2, 2 * c) + muy(1, 1), -s * c * psi_wz() + muy(0, -1), drift(0, -2 * c)); }
  /// (3.29e): (3 cos L0/ω_ie)[−ω_doy cos L0 − ω_ie ψ_ωz/3 + gMUY_z; ω_dox cos L0 − ω_doz sin L0;
  /// ω_doy sin L0 − gMUY_x].
  ExtendedMap u5() const {
    return 3 * c * rows(drift(1, -c) - psi_wz() / 3 + muy(2, 1), drift(0, c) + drift(2, -s), drift(1, s) + muy(0, -1));
  }
  ExtendedMap eps(int first, double scale = 1.0) const {
    return rows(e(first, scale), e(first + 1, scale), e(first + 2, scale));
  }
};

/// (5.4a), (5.4b) for 5.1.1; also the U3 rows the combined scheme takes from it.
ExtendedMap u3_5_4b(const Report& r) {
  const double s = r.s, c = r.c;
  // [[(ζ_rz)_n − (ζ_rz)_p] cos L0 − ε3x; −ε3y; [−(ζ_rx)_n + (ζ_rx)_p] cos L0 − ε3z]
  //   + [−[(ζ_rx)_n − (ζ_rx)_p] sin L0; 0; 0] (2)   (transcription: (ζ_xx)_p is (ζ_rx)_p)
  ExtendedMap m = rows(c * (e(r.zr(2, true)) - e(r.zr(2, false))) - e(z_slot::kU3 + 0), -e(z_slot::kU3 + 1),
                       c * (-e(r.zr(0, true)) + e(r.zr(0, false))) - e(z_slot::kU3 + 2));
  if (!r.sys1) m.row(0) += -s * (e(r.zr(0, true)) - e(r.zr(0, false)));
  return m;
}

/// (5.4a), with the transcription fix of row 1 (subscript n), and (5.7a)'s first bracket.
ExtendedMap u2_5_4a(const Report& r) {
  // [(∂f_rx/g + ζ_ry)_n − (…)_p − ε2x; (∂f_ry/g − ζ_rx)_n − (…)_p − ε2y; −ε2z]
  auto x = [&](bool n) { return ZRow(e(r.fr(0, n), 1 / r.g) + e(r.zr(1, n))); };
  auto y = [&](bool n) { return ZRow(e(r.fr(1, n), 1 / r.g) - e(r.zr(0, n))); };
  return rows(x(true) - x(false) - e(z_slot::kU2 + 0), y(true) - y(false) - e(z_slot::kU2 + 1), -e(z_slot::kU2 + 2));
}

Coefficients printed_5_1_1(const Report& r) {
  Coefficients p = testing::zero_coefficients();
  p[kConst] = r.dr0();
  p[kVel] = r.dv0(true);
  p[kU2] = u2_5_4a(r);
  p[kU3] = u3_5_4b(r);
  p[kU4] = r.u4();  // "The last two terms remain the same as in equation (3.29d, e)."
  p[kU5] = r.u5();
  return p;
}

Coefficients printed_5_1_2(const Report& r) {
  const double s = r.s, c = r.c;
  Coefficients p = testing::zero_coefficients();
  p[kConst] = r.dr0();
  p[kVel] = r.dv0(true);
  // (5.7a): (5.4a) + [−(ω_doy/F(0))_p; (ω_dox/F(0))_p; 0] (1); (ω'_dok/F(0))_n ≈ 0.
  p[kU2] = u2_5_4a(r);
  if (r.sys1) p[kU2] += rows(e(uncertainty_slot::kGyroDrift + 1, -r.f_inv), e(uncertainty_slot::kGyroDrift + 0, r.f_inv), kZero);
  // (5.7b): [0; −ε3y; −(δf_y/g + ζ_x) cos L0] + [[(ζ_rz)_n − (ζ_rz)_p] cos L0 − ε3x; 0; 0] (1)
  //       + [[ζ_z − (δf_y/g + ζ_x) tan L0] cos L0; 0; 0] (2), ζ of the new alignment.
  const ZRow x1 = c * (e(r.zr(2, true)) - e(r.zr(2, false))) - e(z_slot::kU3 + 0);
  const ZRow x2 = c * (r.zeta(2, true) - r.tn * (r.bias(1, 1) + r.zeta(0, true)));
  p[kU3] = rows(r.sys1 ? x1 : x2, -e(z_slot::kU3 + 1), -c * (r.bias(1, 1) + r.zeta(0, true)));
  // (5.7c): (1/ω_ie)[2ω_doz cos L0 + gMUY_y; −gMUY_x; −2ω_ie ε3y cos L0] + (ω_doy/ω_ie)[0; sin L0; 0] (2)
  // (transcription: ω_doy/ω_ie).
  p[kU4] = rows(r.drift(2, 2 * c) + r.muy(1, 1), r.muy(0, -1), -2 * c * e(z_slot::kU3 + 1));
  if (!r.sys1) p[kU4].row(1) += r.drift(1, s);
  // (5.7d): (3 cos L0/ω_ie)[gMUY_z; −ω_doz sin L0; −gMUY_x]
  //       + (1/ω_ie)[−ω_doy(3cos²L0 − 1); 0; 3ω_doy sin L0 cos L0] (2).
  p[kU5] = 3 * c * rows(r.muy(2, 1), r.drift(2, -s), r.muy(0, -1));
  if (!r.sys1) p[kU5] += rows(r.drift(1, -(3 * c * c - 1)), kZero, r.drift(1, 3 * s * c));
  return p;
}

/// End of 5.1.2: "combine these two methods by applying Û3z, respectively Û3x
/// and Û3z for system 2, through integrators to point 2": the 5.1.2 residual
/// with those rows of U'3 taken from 5.1.1's (5.4b).
Coefficients printed_combined(const Report& r) {
  Coefficients p = printed_5_1_2(r);
  const ExtendedMap from_5_1_1 = u3_5_4b(r);
  p[kU3].row(2) = from_5_1_1.row(2);
  if (!r.sys1) p[kU3].row(0) = from_5_1_1.row(0);
  return p;
}

/// What the velocity reset at T gets wrong, ε_ṙ(T) (5.8c): the wiggle at T
/// and the latitude/altitude part of the velocity the computer calculates
/// for a stationary vehicle, (3.23) without (u)V. (The report does not
/// spell ε_ṙ out; the position reset error ε_r(T) is not a separate slot:
/// the computer resets to the position it calculates, i.e. δr(0).)
ExtendedMap eps_rdot(const Report& r) {
  return r.eps(z_slot::kWiggleAtT) +
         rows(kZero, e(uncertainty_slot::kLatitudeError, 2 * r.r0 * r.w * r.s) + e(uncertainty_slot::kAltitudeError, r.w * r.c), kZero);
}

Coefficients printed_5_2(const Report& r) {
  const double wT = r.w * r.T;
  Coefficients p = testing::zero_coefficients();
  // (5.9): δr(0) + ε_r(T) cos ω_s t' + (1/ω_s) ε_ṙ(T) sin ω_s t' + …
  p[kConst] = r.dr0();
  p[kVel] = eps_rdot(r);
  // (5.9a): −E2 − E3 ω_ie T + U4 ½ω_ie²T² (transcription: ε ω_ie T);
  // (5.9b): −E3 + U4 ω_ie T; the last two from (3.29d, e).
  p[kU2] = -r.eps(z_slot::kU2) - wT * r.eps(z_slot::kU3) + 0.5 * wT * wT * r.u4();
  p[kU3] = -r.eps(z_slot::kU3) + wT * r.u4();
  p[kU4] = r.u4();
  p[kU5] = r.u5();
  return p;
}

Coefficients printed_5_3(const Report& r) {
  const double wT = r.w * r.T;
  Coefficients p = testing::zero_coefficients();
  // (5.11b): (δr(0) + ε_r(T)) cos ω_s t' + (1/ω_s) ε_ṙ(T) sin ω_s t' − r0 E (1 − cos ω_s t')
  //   + r0 (ω_ie/ω_s)[−E3 + U4 ω_ie T](ω_s t' − sin ω_s t') + U4, U5 terms;
  // cos ω_s t' = 1 − (1 − cos ω_s t'). E3: the error of the Û3 applied, here the
  // accelerometer slope (5.12) (the report allows either, §5.3).
  p[kConst] = r.dr0();
  p[kVel] = eps_rdot(r);
  p[kU2] = -r.dr0() / r.r0 - r.eps(z_slot::kDfT);
  p[kU3] = -r.eps(z_slot::kU3Accel) + wT * r.u4();
  p[kU4] = r.u4();
  p[kU5] = r.u5();
  return p;
}

Coefficients printed_5_4(const Report& r) {
  const double s = r.s, c = r.c;
  Coefficients p = testing::zero_coefficients();
  p[kConst] = r.dr0();
  p[kVel] = r.dv0(false);
  // (5.20): [∂f_x/g + Δζ_y + ε5x; ∂f_y/g − Δζ_x + ε5y; δg − 2δh/r0 + ε5z], Δζ = ζ − ζ' = ζ_r
  // (ζ' of (5.19) holds ζ_c only); δg read δg/g (transcription) and set as
  // the measurement model sets it, δg/g = −3δh/r0 (§4.1).
  p[kU2] = rows(r.dfc(0, false) + e(uncertainty_slot::kMisalignAlign + 1) + e(z_slot::kAlignAccel + 0),
                r.dfc(1, false) - e(uncertainty_slot::kMisalignAlign + 0) + e(z_slot::kAlignAccel + 1),
                e(uncertainty_slot::kAltitudeError, -3 / r.r0) + e(uncertainty_slot::kAltitudeError, -2 / r.r0) + e(z_slot::kAlignAccel + 2));
  // (5.17a): [−δf_y/g sin L0; (δf_x/g − ζ_cy) sin L0 − ε4x; −(δf_y/g + ζ_x) cos L0]
  //   + [ζ_rz cos L0 − ζ_cx sin L0 + ε4y; 0; 0] (1) + [ζ_z cos L0 − ζ_x sin L0; 0; 0] (2).
  const ZRow x1 = c * e(uncertainty_slot::kMisalignAlign + 2) - s * e(uncertainty_slot::kMisalignConst + 0) + e(z_slot::kTorquerCommands + 1);
  const ZRow x2 = c * r.zeta(2, false) - s * r.zeta(0, false);
  p[kU3] = rows(r.bias(1, -s) + (r.sys1 ? x1 : x2),
                s * (r.bias(0, 1) - e(uncertainty_slot::kMisalignConst + 1)) - e(z_slot::kTorquerCommands + 0),
                -c * (r.bias(1, 1) + r.zeta(0, false)));
  // (5.17b) final line: 2 cos L0 [(−δf_x/g + ζ_cy) cos L0 + ε4z; 0; −(−δf_x/g + ζ_cy) cos L0 − ε4x]
  //   + (g/ω_ie)[MUY_y; −MUY_x; 0] + [0; ω_doy sin L0/ω_ie; 0] (2). As printed: cos L0 in the z row.
  const ZRow cy = r.bias(0, -1) + e(uncertainty_slot::kMisalignConst + 1);
  p[kU4] = rows(2 * c * (c * cy + e(z_slot::kTorquerCommands + 2)) + r.muy(1, 1), r.muy(0, -1),
                2 * c * (-c * cy - e(z_slot::kTorquerCommands + 0)));
  if (!r.sys1) p[kU4].row(1) += r.drift(1, s);
  // (5.17c) simplified (transcription: the stray (1/ω_ie)[MUY_z; 0; −MUY_x] is the merged
  // line (3 cos L0/ω_ie)[gMUY_z; 0; −gMUY_x]) + (1/ω_ie)[−ω_doy(3cos²L0 − 1); 0; 3ω_doy cos L0 sin L0] (2).
  p[kU5] = 3 * c * rows(r.muy(2, 1), kZero, r.muy(0, -1));
  if (!r.sys1) p[kU5] += rows(r.drift(1, -(3 * c * c - 1)), kZero, r.drift(1, 3 * s * c));
  return p;
}

Coefficients printed_none(const Report& r) {
  Coefficients p = testing::zero_coefficients();
  p[kConst] = r.dr0();
  p[kVel] = r.dv0(false);
  p[kU2] = r.u2(false);
  p[kU3] = r.u3(false);
  p[kU4] = r.u4();
  p[kU5] = r.u5();
  return p;
}

Coefficients printed(Scheme scheme, const Report& r) {
  if (scheme == Scheme::kNone) return printed_none(r);
  if (scheme == Scheme::k5_1_1) return printed_5_1_1(r);
  if (scheme == Scheme::k5_1_2) return printed_5_1_2(r);
  if (scheme == Scheme::kCombined) return printed_combined(r);
  if (scheme == Scheme::k5_2) return printed_5_2(r);
  if (scheme == Scheme::k5_3) return printed_5_3(r);
  if (scheme == Scheme::k5_4) return printed_5_4(r);
  return testing::zero_coefficients();
}

// ------------------------------------------------------------ errata

/// Corrections the derivation needs beyond the printed form (zero where the
/// printed form holds), each an erratum of tables/notes/errata.md.
Coefficients errata(Scheme scheme, const Report& r, SchemeForms forms) {
  Coefficients d = testing::zero_coefficients();
  const bool corrected = forms == SchemeForms::kCorrected;
  if (corrected && (scheme == Scheme::k5_2 || scheme == Scheme::k5_3)) {
    // errata.md#5-9: (5.8) carries r0 U5 ω_ie³t³/6 with t = T + t' from the
    // switch-over; (5.9) and (5.11b) print t'³ and drop the cross terms
    // r0 U5 ω_ie³ (3T t'² + 3T² t')/6 of (T + t')³ − T³. On the time functions:
    // t'² = (2/ω_s²)([½ω_s²t'² − (1 − cos)] + (1 − cos)), t' = ((ω_s t' − sin) + sin)/ω_s.
    const double wT = r.w * r.T, q2 = std::pow(r.w / r.ws, 2);
    d[kU4] = wT * r.u5();
    d[kU3] = 0.5 * wT * wT * r.u5();
    d[kU2] = q2 * wT * r.u5();
    // The sin ω_s t' part of the t' term, r0 U5 ω_ie³T²/2 · sin(ω_s t')/ω_s, and
    // −r0 U5 (ω_ie T)³/6 (1 − cos ω_s t'), are the resets' terms the report names
    // as neglected (< 100 ft for T < 20 min): left to the tolerance.
  }
  if (scheme == Scheme::k5_4) {
    // errata.md#5-20: U'2 = U2 − Δf_m/g with (5.19) gives −ε5 and −δg/g where (5.20)
    // prints +ε5 and +δg; with δg/g = −3δh/r0 the z row is +δh/r0, not −5δh/r0.
    // The printed forms keep δg's sign; ε5's sign (a zero-mean error, not
    // reproduced: the measurement is one slot) differs in both.
    d[kU2] = -2 * r.eps(z_slot::kAlignAccel);
    if (corrected) d[kU2].row(2) += e(uncertainty_slot::kAltitudeError, 6 / r.r0);
    // errata.md#5-17b: the z row of U'4 is −2 cos L0 (C_y sin L0 + ε4x) (from
    // (5.16a) in (3.29d)); the final line prints C_y cos L0, which the
    // printed forms keep. Zero at 45°. (ζ_ry is not in C_y: it enters at
    // switch-over, C' = C + ζ_r (2.18a), after the commands measured C.)
    const ZRow cy = r.bias(0, -1) + e(uncertainty_slot::kMisalignConst + 1);
    if (corrected) d[kU4].row(2) = 2 * r.c * (r.c - r.s) * cy;
  }
  return d;
}

// ------------------------------------------------------------ tolerances

/// What a printed form says it neglects, as a per-term tolerance.
struct Neglect {
  enum Kind {
    kRoundoff,     ///< the printed form is exact at the paper level
    kCoefficient,  ///< |Δcoefficient| × magnitude ≤ level (dimensionless, like the U's)
    kFeet,         ///< |Δcoefficient| × magnitude × max over 1..90 min of its time function ≤ level ft
  } kind;
  double level;
  const char* source;
};

// Round-off of the projection (QR on the column-scaled design, data up to
// ~1e7 ft per unit): measured below 1e-5 ft at the bound for every exact
// term and 1e-10 ft off the span; 0.01 ft is far below any printed digit.
constexpr double kRoundoffFt = 0.01;
constexpr Neglect kExact{Neglect::kRoundoff, kRoundoffFt, "exact"};
// (5.4b): "where terms less than 10^-4 have been neglected".
constexpr Neglect k5_4Terms{Neglect::kCoefficient, 1e-4, "(5.4b): terms < 1e-4 neglected"};
// (5.7d): "where terms less than 10^-3 have been neglected" (for (5.7a–d)).
constexpr Neglect k5_7Terms{Neglect::kCoefficient, 1e-3, "(5.7): terms < 1e-3 neglected"};
// (5.9): "terms r0 (ω_ie/ω_s) U5 ½ω_ie²T² and U5 ω_ie³T³/6 neglected because they give
// errors less than 100 feet for T < 20 minutes"; (5.11b) omits the same terms.
constexpr Neglect k5_9Terms{Neglect::kFeet, 100.0, "(5.9), (5.11b): reset terms < 100 ft for T <= 20 min"};
// (5.17a, b): "making the same simplifications as were done for equation (3.29c)":
// §3.4 drops terms below 1,300 ft after 1.5 h.
constexpr Neglect k3_29Terms{Neglect::kFeet, 1300.0, "(5.17a, b) as (3.29): terms < 1,300 ft after 1.5 h"};
// (5.17c): "neglecting terms giving less than 260 feet during a one and a half hour run".
constexpr Neglect k5_17cTerms{Neglect::kFeet, 260.0, "(5.17c): terms < 260 ft over 1.5 h"};

std::array<Neglect, kFns> neglect(Scheme scheme) {
  if (scheme == Scheme::kNone) return {kExact, kExact, kExact, kExact, kExact, kExact};
  if (scheme == Scheme::k5_1_1) return {kExact, kExact, k5_4Terms, k5_4Terms, k5_4Terms, k5_4Terms};
  if (scheme == Scheme::k5_1_2 || scheme == Scheme::kCombined)
    return {kExact, kExact, k5_7Terms, k5_7Terms, k5_7Terms, k5_7Terms};
  if (resets_at_test_end(scheme)) return {k5_9Terms, k5_9Terms, k5_9Terms, k5_9Terms, k5_9Terms, k5_9Terms};
  if (scheme == Scheme::k5_4) return {kExact, kExact, kExact, k3_29Terms, k3_29Terms, k5_17cTerms};
  return {};
}

/// The size of a coefficient difference in the units of its rule.
double term_size(const Neglect& rule, int fn, double difference, double magnitude, const ModelOptions& m) {
  if (rule.kind == Neglect::kCoefficient && fn >= kU2) return std::abs(difference) * magnitude;
  return std::abs(difference) * magnitude * testing::time_function_max(fn, m) / kFtToM;  // ft
}
double rule_level(const Neglect& rule, int fn) {
  return rule.kind == Neglect::kCoefficient && fn < kU2 ? kRoundoffFt : rule.level;
}

// ------------------------------------------------------------ the comparison

struct Case {
  Scheme scheme;
  System system;
  double latitude_deg = 45.0;
  double test_duration_min = 15.0;
};

std::string describe(const Case& c) {
  return fmt::format("scheme {}, system {}, L0 = {} deg, T = {} min", to_string(c.scheme), system_number(c.system),
                     c.latitude_deg, c.test_duration_min);
}

/// Terms the report neglects although they exceed its own stated cut. Each
/// is asserted to lie just above the cut (in (1, kMaxExcess] of it), so the
/// finding is pinned down exactly; errata.md#5-7 records them.
struct Exceedance {
  Scheme scheme;
  System system;
  int fn, axis, perturbation;
};
constexpr Exceedance kExceedances[] = {
    // 5.1.2 (and combined, which shares U'5): ω'_doy of (5.6a) carries −ω_ie (u)ψ cos L0
    // into U'5 = (3 cos L0/ω_ie)[−ω'_doy cos L0 …; …; ω'_doy sin L0 …] (3.29e):
    // 3 cos³L0 (u)ψ = 1.06e-3 at 1 mrad, above (5.7)'s 1e-3 cut.
    {Scheme::k5_1_2, System::kTheodolite, kU5, 0, uncertainty_slot::kTheodolite},
    {Scheme::k5_1_2, System::kTheodolite, kU5, 2, uncertainty_slot::kTheodolite},
    {Scheme::kCombined, System::kTheodolite, kU5, 0, uncertainty_slot::kTheodolite},
    {Scheme::kCombined, System::kTheodolite, kU5, 2, uncertainty_slot::kTheodolite},
};
constexpr double kMaxExcess = 1.07;  // 1.06 rounds to the report's one-digit "10^-3"

bool is_exceedance(Scheme s, System sys, int fn, int axis, int q) {
  for (const Exceedance& x : kExceedances)
    if (x.scheme == s && x.system == sys && x.fn == fn && x.axis == axis && x.perturbation == q) return true;
  return false;
}

struct Agreement {
  double worst_fraction = 0;  ///< max of term size / tolerance over the terms (≤ 1 passes)
  std::string worst_term;
  double printed_alone_fraction = 0;  ///< max of term size / tolerance with the printed form alone
  double largest_erratum_ft = 0;      ///< the largest correction, ft at the bound over 1.5 h
  std::string largest_erratum;
  double worst_residual_ft = 0;  ///< distance of δr from the span of the time functions, ft at the bound
};

Agreement compare(const Case& k, SchemeForms forms) {
  ModelOptions m;
  m.latitude_rad = k.latitude_deg * kDegToRad;
  TestRunOptions test;
  test.duration_s = k.test_duration_min * 60.0;
  const testing::FitResult fit = testing::scheme_coefficients(k.scheme, k.system, m, test, forms);
  Agreement a;
  // At the paper level every scheme's δr(t) lies in the span of the six time functions.
  for (int q = 0; q < z_slot::kDim; ++q) {
    const double ft = fit.worst_residual_m[q] * testing::magnitude(q, m, test) / kFtToM;
    a.worst_residual_ft = std::max(a.worst_residual_ft, ft);
    EXPECT_LE(ft, kRoundoffFt) << describe(k) << ": δr per " << testing::perturbation_name(q)
                               << " is not a sum of the time functions";
  }
  const Report r(k.system, m, test);
  const Coefficients p = printed(k.scheme, r), d = errata(k.scheme, r, forms);
  const std::array<Neglect, kFns> rules = neglect(k.scheme);
  for (int fn = 0; fn < kFns; ++fn) {
    for (int axis = 0; axis < 3; ++axis) {
      for (int q = 0; q < z_slot::kDim; ++q) {
        const double mag = testing::magnitude(q, m, test);
        const double got = fit.c[fn](axis, q), want = p[fn](axis, q) + d[fn](axis, q);
        const double size = term_size(rules[fn], fn, got - want, mag, m), level = rule_level(rules[fn], fn);
        const std::string where =
            fmt::format("{} {} row {} per {}", describe(k), kFnNames[fn], "xyz"[axis], testing::perturbation_name(q));
        if (is_exceedance(k.scheme, k.system, fn, axis, q)) {
          EXPECT_GT(size, level) << where << ": listed as exceeding the report's cut, but within it";
          EXPECT_LE(size, kMaxExcess * level) << where << ": exceeds the report's cut by more than recorded";
          std::cout << fmt::format("  exceedance: {}: neglected term {:.3g}, the report's cut {:.3g}\n", where, size,
                                   level);
          continue;
        }
        EXPECT_LE(size, level) << where << ": derived " << got << ", printed " << p[fn](axis, q) << " + erratum "
                               << d[fn](axis, q) << " (" << rules[fn].source << ")";
        if (size / level > a.worst_fraction) a.worst_fraction = size / level, a.worst_term = where;
        if (d[fn](axis, q) == 0.0) continue;
        // How far the printed term alone is from the derivation.
        const double printed_alone = term_size(rules[fn], fn, got - p[fn](axis, q), mag, m) / level;
        if (printed_alone > a.printed_alone_fraction)
          a.printed_alone_fraction = printed_alone, a.largest_erratum = where;
        a.largest_erratum_ft =
            std::max(a.largest_erratum_ft, std::abs(d[fn](axis, q)) * mag * testing::time_function_max(fn, m) / kFtToM);
      }
    }
  }
  // An erratum is claimed only where it matters: without it the printed form
  // is outside its own tolerance.
  if (a.largest_erratum_ft > 0) {
    EXPECT_GT(a.printed_alone_fraction, 1.0)
        << describe(k) << ": errata claimed but the printed form is within tolerance";
  }
  return a;
}

constexpr Case kCases[] = {
    {Scheme::kNone, System::kTheodolite},        {Scheme::kNone, System::kGyrocompass},
    {Scheme::k5_1_1, System::kTheodolite},       {Scheme::k5_1_1, System::kGyrocompass},
    {Scheme::k5_1_2, System::kTheodolite},       {Scheme::k5_1_2, System::kGyrocompass},
    {Scheme::kCombined, System::kTheodolite},    {Scheme::kCombined, System::kGyrocompass},
    {Scheme::k5_2, System::kTheodolite, 45, 10}, {Scheme::k5_2, System::kGyrocompass, 45, 10},
    {Scheme::k5_2, System::kTheodolite, 45, 15}, {Scheme::k5_2, System::kGyrocompass, 45, 15},
    {Scheme::k5_2, System::kTheodolite, 45, 20}, {Scheme::k5_2, System::kGyrocompass, 45, 20},
    {Scheme::k5_3, System::kTheodolite, 45, 10}, {Scheme::k5_3, System::kGyrocompass, 45, 10},
    {Scheme::k5_3, System::kTheodolite, 45, 15}, {Scheme::k5_3, System::kGyrocompass, 45, 15},
    {Scheme::k5_3, System::kTheodolite, 45, 20}, {Scheme::k5_3, System::kGyrocompass, 45, 20},
    {Scheme::k5_4, System::kTheodolite},         {Scheme::k5_4, System::kGyrocompass},
};

TEST(CompensationResiduals, DerivedCoefficientsMatchThePrintedMatricesTermByTerm) {
  for (SchemeForms forms : {SchemeForms::kCorrected, SchemeForms::kPrinted})
  for (const Case& k : kCases) {
    const Agreement a = compare(k, forms);
    std::cout << fmt::format("{:<46} {} forms: worst term {:.3f} of its tolerance [{}]; off-span {:.1e} ft\n",
                             describe(k), forms == SchemeForms::kPrinted ? "printed" : "corrected", a.worst_fraction,
                             a.worst_term, a.worst_residual_ft);
    if (a.largest_erratum_ft > 0)
      std::cout << fmt::format(
          "  printed form alone: worst term {:.1f} of its tolerance [{}]; largest erratum {:.0f} "
          "ft at the bound over 1.5 h\n",
          a.printed_alone_fraction, a.largest_erratum, a.largest_erratum_ft);
  }
}

// errata.md#5-17b: (5.17b)'s last line writes the z row of U'4 with cos L0 where
// (5.16a) in (3.29d) gives sin L0. At 45° they are equal; at L0 = 10° they are
// 2 cos L0 (cos L0 − sin L0)·δf_x/g apart, beyond the 1,300 ft of the (3.29)
// simplifications at 1 mg: the linear-in-x forms give sin L0, the paper level
// the printed cos L0.
TEST(CompensationResiduals, Equation517bZRowIsSinL0DerivedAndCosL0AsPrinted) {
  ModelOptions m;
  m.latitude_rad = 10.0 * kDegToRad;
  const TestRunOptions test;
  const double s = std::sin(m.latitude_rad), c = std::cos(m.latitude_rad), g = m.gravity_mps2;
  const double u4_ft_per_unit = testing::time_function_max(kU4, m) / kFtToM;
  for (System sys : {System::kTheodolite, System::kGyrocompass}) {
    const int q = uncertainty_slot::kAccelBias + 0;  // C_y = −δf_x/g + ζ_cy + …
    const double sin_reading = 2 * c * s / g, cos_reading = 2 * c * c / g;
    const double derived = testing::scheme_coefficients(Scheme::k5_4, sys, m, test, SchemeForms::kCorrected).c[kU4](2, q);
    const double printed = testing::scheme_coefficients(Scheme::k5_4, sys, m, test, SchemeForms::kPrinted).c[kU4](2, q);
    EXPECT_NEAR(derived, sin_reading, 1e-9 * sin_reading) << "system " << system_number(sys);
    EXPECT_NEAR(printed, cos_reading, 1e-9 * cos_reading) << "system " << system_number(sys);
    // C_y as printed, −δf_x/g + ζ_cy: the ζ_cy column is −g times δf_x's in
    // both forms, and ζ_ry (which enters after the commands measured C) has
    // none at the paper level either.
    for (SchemeForms forms : {SchemeForms::kCorrected, SchemeForms::kPrinted}) {
      const testing::FitResult fit = testing::scheme_coefficients(Scheme::k5_4, sys, m, test, forms);
      EXPECT_NEAR(fit.c[kU4](2, uncertainty_slot::kMisalignConst + 1), -g * fit.c[kU4](2, q), 1e-9 * g * std::abs(fit.c[kU4](2, q)));
      EXPECT_NEAR(fit.c[kU4](2, uncertainty_slot::kMisalignAlign + 1), 0.0, 1e-12) << "system " << system_number(sys);
    }
    const double printed_off_ft = std::abs(derived - cos_reading) * default_bounds()[q] * u4_ft_per_unit;
    EXPECT_GT(printed_off_ft, k3_29Terms.level) << "system " << system_number(sys);
    std::cout << fmt::format(
        "system {}, L0 = 10 deg: U'4z per δf_x = {:.4g}/g derived (sin L0 reading {:.4g}/g), {:.4g}/g at the paper "
        "level (printed cos L0 reading {:.4g}/g): {:.0f} ft apart over 1.5 h at 1 mg\n",
        system_number(sys), derived * g, sin_reading * g, printed * g, cos_reading * g, printed_off_ft);
  }
}

// End of 5.1.2, model against model: the combined scheme's residual equals
// 5.1.2's except the U'3 rows whose Û3 goes through integrators (z for
// system 1; x and z for system 2), which equal 5.1.1's.
TEST(CompensationResiduals, CombinedIs512WithThe511RowsOfU3) {
  const ModelOptions m;
  const TestRunOptions test;
  for (System sys : {System::kTheodolite, System::kGyrocompass}) {
    const Coefficients comb = testing::scheme_coefficients(Scheme::kCombined, sys, m, test, SchemeForms::kPrinted).c;
    const Coefficients c511 = testing::scheme_coefficients(Scheme::k5_1_1, sys, m, test, SchemeForms::kPrinted).c;
    const Coefficients c512 = testing::scheme_coefficients(Scheme::k5_1_2, sys, m, test, SchemeForms::kPrinted).c;
    const Eigen::Matrix3d integrated = scheme_terms::combined_integrator_selection(sys);
    for (int fn = 0; fn < kFns; ++fn) {
      for (int axis = 0; axis < 3; ++axis) {
        const bool from_511 = fn == kU3 && integrated(axis, axis) == 1.0;
        const auto& want = from_511 ? c511[fn] : c512[fn];
        for (int q = 0; q < z_slot::kDim; ++q) {
          const double scale = testing::magnitude(q, m, test) * testing::time_function_max(fn, m) / kFtToM;
          EXPECT_LE(std::abs(comb[fn](axis, q) - want(axis, q)) * scale, kRoundoffFt)
              << "system " << system_number(sys) << " " << kFnNames[fn] << " row "
              << "xyz"[axis] << " per " << testing::perturbation_name(q)
              << (from_511 ? " (from 5.1.1)" : " (from 5.1.2)");
        }
      }
    }
  }
}

// errata.md#5-9: (5.8) carries the U5 term as r0 U5 ω_ie³t³/6 with t from
// the switch-over, but (5.9) and (5.11b) print t'³ (t' = t − T), as if the
// t³ growth restarted at the reset. Independent arbiter: the linear level
// (the error ODE integrated, resets applied to its state) follows the
// uncompensated curve from time T, δr(T + t') − δr(T), so the error at a
// given t' grows with T; the printed form does not depend on T at all.
// Shown with g·MUY_z at 10 meru (a pure U5 uncertainty at the paper level:
// no U2, U3 content to estimate), x axis, t' = 84 min, T = 5 and 20 min.
TEST(CompensationResiduals, Equations59And511bRestartTheU5GrowthAtTheReset) {
  const ModelOptions m;
  const int j = uncertainty_slot::kGyroMuyDrift + 2;
  const double x = 10 * kMeruToRadps, tp = 84 * 60.0, w = m.earth_rate_radps;
  const double u5 = 3 * std::cos(m.latitude_rad) / w * x;  // (3.29e) x row
  const double printed_ft = m.radius_m * u5 * std::pow(w * tp, 3) / 6 / kFtToM;
  // 5.2 at [the paper level (printed forms), its corrected forms, the linear level][T = 5, 20 min].
  double at[3][2];
  for (int f = 0; f < 3; ++f) {
    const Fidelity fid = f < 2 ? Fidelity::kPaper : Fidelity::kLinear;
    const SchemeForms forms = f == 0 ? SchemeForms::kPrinted : SchemeForms::kCorrected;
    for (int k = 0; k < 2; ++k) {
      TestRunOptions test;
      test.duration_s = (k == 0 ? 5 : 20) * 60.0;
      const auto error_ft = [&](Scheme s) {
        return scheme_position_maps(s, System::kTheodolite, fid, m, test, {tp}, forms).position[0](0, j) * x / kFtToM;
      };
      at[f][k] = error_ft(Scheme::k5_2);
      if (fid == Fidelity::kPaper) {
        // 5.3 resets the same way; it differs from 5.2 only in the estimate slots.
        EXPECT_NEAR(error_ft(Scheme::k5_3), at[f][k], 1e-9 * std::abs(at[f][k]));
      } else {
        // The linear level after the resets: the uncompensated curve from T.
        const auto none = position_maps(System::kTheodolite, fid, m, {test.duration_s, test.duration_s + tp});
        const double continued = (none[1](0, j) - none[0](0, j)) * x / kFtToM;
        EXPECT_NEAR(at[f][k], continued, 0.01 * std::abs(continued)) << "T = " << test.duration_s;
      }
    }
  }
  const double corrected_ratio = at[1][1] / at[1][0], linear_ratio = at[2][1] / at[2][0];
  std::cout << fmt::format(
      "5.2/5.3: x error at t' = 84 min for g·MUY_z = 10 meru: paper level (printed) {:.0f}, {:.0f} ft "
      "(T = 5, 20 min); corrected forms {:.0f}, {:.0f} ft; linear level {:.0f}, {:.0f} ft; printed (5.9)/(5.11b) "
      "t'^3 term {:.0f} ft for any T\n",
      at[0][0], at[0][1], at[1][0], at[1][1], at[2][0], at[2][1], printed_ft);
  // The paper level is the printed form: the t'^3 term, whatever T.
  EXPECT_NEAR(at[0][0], printed_ft, 1e-9 * printed_ft);
  EXPECT_NEAR(at[0][1], printed_ft, 1e-9 * printed_ft);
  EXPECT_GT(linear_ratio, 1.4) << "the linear level should grow with T";
  EXPECT_NEAR(corrected_ratio, linear_ratio, 0.05 * linear_ratio) << "the corrected forms with (T + t')^3 − T^3";
  // The corrected forms agree with the printed t'^3 term only for T → 0.
  EXPECT_GT(at[1][1] - printed_ft, 10 * k5_9Terms.level);
}

}  // namespace
}  // namespace insmc
