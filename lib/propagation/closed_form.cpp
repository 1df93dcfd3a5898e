#include "lib/propagation/closed_form.h"

#include <cmath>

namespace insmc {

ClosedFormCoefficients closed_form_3_27(double t, const ModelOptions& o, Form327 form) {
  const double w = o.earth_rate_radps, ws = o.schuler_radps();
  const double q = w / ws, e = q * q, q3 = q * q * q;  // ω_ie/ω_s, ε = (ω_ie/ω_s)², (ω_ie/ω_s)³
  const double p = w * t, ss = std::sin(ws * t), cs1 = 1.0 - std::cos(ws * t);
  const double s = std::sin(p), c = std::cos(p), c1 = 1.0 - c, v = p - s;
  const double s2 = std::sin(2 * p), c21 = 1.0 - std::cos(2 * p);
  ClosedFormCoefficients f{};
  // δr(0) + r0[(K1 − δr(0)/r0) …](1 − cos ω_s t)  ⇒  δr(0) cos ω_s t.
  f.initial_position = 1.0 - cs1;
  f.initial_velocity_s = ss / ws;
  // Collected per K_j from (3.27):
  //  sin ω_s t:      −(ω_ie/ω_s)[K2 + (1 + ε)K3] + (ω_ie/ω_s)³(3K6 + K7 + 3K8)
  //  1 − cos ω_s t:  K1 − ε(K4 + 2K5)
  //  K2 ω_ie t;  [K3(1 + ε) + ε(K6 − K7)] sin;  [K4(1 + ε) + ε(2K5 + 2K10)](1 − cos)
  //  K5(1 + ε) φ sin;  K6(1 + ε) φ(1 − cos);  [K7 − (ω_ie/ω_s)³ K6](φ − sin)
  //  [K8(1 + ε) − 3εK11] sin(1 − cos);  K9(1 + ε)(1 − cos)²;  K10(1 + ε) sin(φ − sin)
  //  K11(φ − sin)(1 − cos) + εK11 cos(φ − sin)
  //  −(3/2)εK8 sin 2φ − (3/2)ε(K9 + K10)(1 − cos 2φ)
  f.k[0] = cs1;
  f.k[1] = -q * ss + p;
  f.k[2] = -q * (1 + e) * ss + (1 + e) * s;
  f.k[3] = -e * cs1 + (1 + e) * c1;
  f.k[4] = -2 * e * cs1 + 2 * e * c1 + (1 + e) * p * s;
  if (form == Form327::kPrinted) {
    f.k[5] = 3 * q3 * ss + e * s + (1 + e) * p * c1 - q3 * v;
  } else {
    // Exact particular solution for g φ(1 − cos φ): r0[φ − φ cos φ/(1 − ε)
    // − 2ε sin φ/(1 − ε)²] plus 3(ω_ie/ω_s)³ sin ω_s t for the initial
    // conditions; to first order in ε this is the line below.
    f.k[5] = 3 * q3 * ss - 3 * e * s + (1 + e) * p * c1 - e * v;
  }
  f.k[6] = q3 * ss - e * s + v;
  f.k[7] = 3 * q3 * ss + (1 + e) * s * c1 - 1.5 * e * s2;
  f.k[8] = (1 + e) * c1 * c1 - 1.5 * e * c21;
  f.k[9] = 2 * e * c1 + (1 + e) * s * v - 1.5 * e * c21;
  f.k[10] = -3 * e * s * c1 + v * c1 + e * c * v;
  return f;
}

ClosedFormCoefficients closed_form_3_28(double t, const ModelOptions& o) {
  const double w = o.earth_rate_radps, ws = o.schuler_radps();
  const double q = w / ws, e = q * q;
  const double p = w * t, ss = std::sin(ws * t), cs1 = 1.0 - std::cos(ws * t);
  const double s = std::sin(p), c1 = 1.0 - std::cos(p), v = p - s;
  ClosedFormCoefficients f{};
  f.initial_position = 1.0 - cs1;
  f.initial_velocity_s = ss / ws;
  // (3.28): sin ω_s t: −(ω_ie/ω_s)(K2 + K3); 1 − cos ω_s t: K1 − ε(K4 + 2K5);
  // then K2 φ + K3 sin + K4(1 − cos) + … + K11(φ − sin)(1 − cos).
  f.k[0] = cs1;
  f.k[1] = -q * ss + p;
  f.k[2] = -q * ss + s;
  f.k[3] = -e * cs1 + c1;
  f.k[4] = -2 * e * cs1 + p * s;
  f.k[5] = p * c1;
  f.k[6] = v;
  f.k[7] = s * c1;
  f.k[8] = c1 * c1;
  f.k[9] = s * v;
  f.k[10] = c1 * v;
  return f;
}

ShortRunFunctions short_run_functions_3_29(double t, const ModelOptions& o) {
  const double w = o.earth_rate_radps, ws = o.schuler_radps();
  const double q = w / ws, x = ws * t;
  ShortRunFunctions f{};
  f.initial_position = 1.0;
  f.initial_velocity_s = std::sin(x) / ws;
  f.u2 = 1.0 - std::cos(x);
  f.u3 = q * (x - std::sin(x));
  f.u4 = q * q * (0.5 * x * x - (1.0 - std::cos(x)));
  const double p = w * t;
  f.u5 = p * p * p / 6.0;
  return f;
}

double u5_function_3_30(double t, const ModelOptions& o) {
  const double w = o.earth_rate_radps, ws = o.schuler_radps();
  const double q = w / ws, x = ws * t;
  return q * q * q * (x * x * x / 6.0 - (x - std::sin(x)));
}

}  // namespace insmc
