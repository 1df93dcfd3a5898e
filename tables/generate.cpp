#include "tables/generate.h"

#include <algorithm>
#include <cmath>
#include <fmt/core.h>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>

#include "lib/common/input_error.h"
#include "lib/preflight/observables.h"
#include "lib/propagation/closed_form.h"
#include "lib/propagation/linear_model.h"
#include "lib/propagation/paper_model.h"
#include "lib/uncertainty/catalogue.h"
#include "lib/units/units.h"
#include "tables/printed.h"
#include "tables/residual_maps.h"

namespace insmc::tables {

std::string_view to_string(TableConvention c) {
  switch (c) {
    case TableConvention::kPaper: return "paper";
    case TableConvention::kCorrected: return "corrected";
  }
  return "?";
}

TableConvention parse_table_convention(std::string_view text, std::string_view field) {
  if (text == "paper") return TableConvention::kPaper;
  if (text == "corrected") return TableConvention::kCorrected;
  throw InputError(std::string(field), std::string(text), "must be paper or corrected");
}

namespace {

// ---- units of the printed tables --------------------------------------------
constexpr double kMg = kMgToMps2;
constexpr double kUg = kUgToMps2;
constexpr double kMeru = kMeruToRadps;
constexpr double kMrad = kMradToRad;
constexpr double kUrad = kUradToRad;
constexpr double kFt = kFtToM;
constexpr double kPpm = kPpmToUnit;

/// Step of the finite differences that give the Taylor coefficients of the
/// linear model's forcing at t = 0. Five-point stencils: truncation
/// ~ (ω_ie h)⁴/90 ≈ 1e-11 and round-off ~ 1e-16/(ω_ie h)² ≈ 1e-11, relative.
constexpr double kTaylorStepS = 60.0;

/// RK4 step for the Schuler ODE: error ~ (ω_s h)⁴ ≈ 4e-11 per Schuler period.
constexpr double kOdeMaxStepS = 2.0;

// ---- row specifications -------------------------------------------------------

/// Which quantity a row prints.
enum class Kind {
  kAccel,        ///< accelerometer output error Δf^a (4.4): g × coefficient × time function
  kPosition,     ///< position error per uncertainty: coefficient × (4.5)/(3.29) time function
  kCoefficient,  ///< position error per unit of a residual coefficient (Table 5.1 rows 1–3)
};

/// Which coefficient matrix and time function.
enum class Term { kA1, kU2, kU3, kU4, kU5, kDV };

/// Which coefficient maps hold the row's uncertainties.
enum class Maps {
  kUncompensated,  ///< (3.22), (3.23), (3.29b–e), A1 (4.4b): the test run, and scheme 5.1.1's U4, U5
  kScheme54,       ///< scheme 5.4 residuals (5.20), (5.17a–c) (residual_maps.h)
};

/// What kCorrected uses for the row.
enum class Reference {
  kLinear,     ///< the linear model (forcing split in Taylor orders, Schuler ODE)
  kPaperMaps,  ///< the maps above with cos L_0 on g·MUY and the U5 function of (3.30)
};

struct Member {
  std::string label;  ///< "" when the printed row has one member
  System system;
  int axis;    ///< 0, 1, 2 = x, y, z of a'
  int column;  ///< catalogue slot or map_column:: extra column
};

struct RowSpec {
  Kind kind;
  Term term;
  double per_unit_si;  ///< one unit of the row's uncertainty (or coefficient), SI
  double out_unit_si;  ///< the printed output unit, SI
  std::vector<Member> members;
  Maps maps = Maps::kUncompensated;
  Reference corrected = Reference::kLinear;
};

struct Sym {
  std::string label;
  int column;
  int axis;
};

enum class Systems { k1, k2, kBoth };

std::vector<Member> expand(const std::vector<Sym>& syms, Systems systems) {
  std::vector<System> list;
  if (systems != Systems::k2) list.push_back(System::kTheodolite);
  if (systems != Systems::k1) list.push_back(System::kGyrocompass);
  const bool single = syms.size() * list.size() == 1;
  std::vector<Member> out;
  for (const Sym& s : syms)
    for (System sys : list) {
      std::string label;
      if (!single)
        label = list.size() > 1 ? fmt::format("{}, sys {}", s.label, system_number(sys)) : s.label;
      out.push_back({label, sys, s.axis, s.column});
    }
  return out;
}

constexpr int X = 0, Y = 1, Z = 2;

/// The specification of every printed row of Tables 4.1, 4.2, 5.1, 5.2, keyed
/// by (table, printed row). The meaning of each row: tables/notes/tables.md.
std::map<std::pair<std::string, std::string>, RowSpec> row_specs(const ModelOptions& o) {
  using K = Kind;
  using T = Term;
  const Systems s1 = Systems::k1, s2 = Systems::k2, s12 = Systems::kBoth;
  // One μrad of leveling error ψ_ω = ω_do/F(0) (system 1) is F(0)·1 μrad of drift.
  const double psi_urad = o.leveling_gain_ratio * o.earth_rate_radps * kUrad;
  const Sym dfx{"δf_x", uncertainty_slot::kAccelBias + 0, X}, dfy{"δf_y", uncertainty_slot::kAccelBias + 1, Z},
      dfz{"δf_z", uncertainty_slot::kAccelBias + 2, Z};
  const Sym pfx{"∂f_x", uncertainty_slot::kBiasChangeConst + 0, X}, pfy{"∂f_y", uncertainty_slot::kBiasChangeConst + 1, Y};
  const Sym az{"a_z", uncertainty_slot::kAccelScale + 2, Z};
  const Sym wdx_y{"ω_dox", uncertainty_slot::kGyroDrift + 0, Y}, wdy_x{"ω_doy", uncertainty_slot::kGyroDrift + 1, X},
      wdz_x{"ω_doz", uncertainty_slot::kGyroDrift + 2, X}, wdy_y{"ω_doy", uncertainty_slot::kGyroDrift + 1, Y};
  const Sym mux_y{"gMUY_x", uncertainty_slot::kGyroMuyDrift + 0, Y}, muy_x{"gMUY_y", uncertainty_slot::kGyroMuyDrift + 1, X},
      muz_x{"gMUY_z", uncertainty_slot::kGyroMuyDrift + 2, X};
  const Sym zx_y{"ζ_x", uncertainty_slot::kMisalignConst + 0, Y}, zy_x{"ζ_y", uncertainty_slot::kMisalignConst + 1, X},
      zz_x{"ζ_z", uncertainty_slot::kMisalignConst + 2, X};
  const Sym upsi{"(u)ψ", uncertainty_slot::kTheodolite, X};
  const Sym psix{"ω_dox/F(0)", uncertainty_slot::kGyroDrift + 0, Y}, psiy{"ω_doy/F(0)", uncertainty_slot::kGyroDrift + 1, X};
  const Sym vx{"δV(0)_x", uncertainty_slot::kInitialVelocity + 0, X}, vy{"δV(0)_y", uncertainty_slot::kInitialVelocity + 1, Y},
      vz{"δV(0)_z", uncertainty_slot::kInitialVelocity + 2, Z};

  std::map<std::pair<std::string, std::string>, RowSpec> s;
  auto add = [&s](std::string table, std::string row, RowSpec spec) {
    s.emplace(std::make_pair(std::move(table), std::move(row)), std::move(spec));
  };

  // ---- Table 4.1: Δf^a = g{A1 + U3 ω_ie t + U4 ½(ω_ie t)²} (4.4), per unit, at 45°.
  add("4.1", "1&2 | δf_y | U3", {K::kAccel, T::kU3, kMg, kMg, expand({dfy}, s12)});
  add("4.1", "1&2 | δf_z, δg, ∂f_x, ∂f_y | A1",
      {K::kAccel, T::kA1, kMg, kMg,
       expand({dfz, {"δg", map_column::kGravityError, Z}, pfx, pfy}, s12)});
  add("4.1", "1&2 | a_z | A1", {K::kAccel, T::kA1, kPpm, kUg, expand({az}, s12)});
  add("4.1", "1 | ω_dox, ω_doy | U3", {K::kAccel, T::kU3, kMeru, kUg, expand({wdx_y, wdy_x}, s1)});
  add("4.1", "1 | ω_doz | U4", {K::kAccel, T::kU4, kMeru, kUg, expand({wdz_x}, s1)});
  add("4.1", "1 | ω_dox/F(0), ω_doy/F(0) | A1",
      {K::kAccel, T::kA1, psi_urad, kUg, expand({psix, psiy}, s1)});
  add("4.1", "2 | ω_dox | U3", {K::kAccel, T::kU3, kMeru, kUg, expand({wdx_y}, s2)});
  add("4.1", "2 | ω_doy, ω_doz | U4", {K::kAccel, T::kU4, kMeru, kUg, expand({wdy_y, wdz_x}, s2)});
  add("4.1", "1&2 | gMUY_x, gMUY_y | U4", {K::kAccel, T::kU4, kMeru, kUg, expand({mux_y, muy_x}, s12)});
  add("4.1", "1&2 | ζ_x, ζ_y | A1", {K::kAccel, T::kA1, kMrad, kMg, expand({zx_y, zy_x}, s12)});
  add("4.1", "1&2 | ζ_z | U3", {K::kAccel, T::kU3, kMrad, kMg, expand({zz_x}, s12)});
  add("4.1", "1 | (u)ψ | U3", {K::kAccel, T::kU3, kMrad, kMg, expand({upsi}, s1)});

  // ---- Table 4.2: Δr^{a'} = δr − δr(0) (4.5), per unit, at 45°.
  add("4.2", "1&2 | δf_y | U3", {K::kPosition, T::kU3, kMg, kFt, expand({dfy}, s12)});
  // δf_x, δf_y do not enter U2 (3.29b); the row means the bias changes ∂f_x, ∂f_y, as in Table 4.1.
  add("4.2", "1&2 | δf_z, δf_x, δf_y | U2",
      {K::kPosition, T::kU2, kMg, kFt,
       expand({dfz, {"∂f_x (printed δf_x)", pfx.column, X}, {"∂f_y (printed δf_y)", pfy.column, Y}},
              s12)});
  add("4.2", "1&2 | a_z | U2", {K::kPosition, T::kU2, kPpm, kFt, expand({az}, s12)});
  add("4.2", "1&2 | ω_dox | U3", {K::kPosition, T::kU3, kMeru, kFt, expand({wdx_y}, s12)});
  add("4.2", "1 | ω_doy | U3", {K::kPosition, T::kU3, kMeru, kFt, expand({wdy_x}, s1)});
  add("4.2", "1&2 | ω_doz | U4", {K::kPosition, T::kU4, kMeru, kFt, expand({wdz_x}, s12)});
  add("4.2", "1 | ω_dox/F(0), ω_doy/F(0) | U2",
      {K::kPosition, T::kU2, psi_urad, kFt, expand({psix, psiy}, s1)});
  add("4.2", "1&2 | gMUY_x, gMUY_y | U4", {K::kPosition, T::kU4, kMeru, kFt, expand({mux_y, muy_x}, s12)});
  add("4.2", "1&2 | ζ_x, ζ_y | U2", {K::kPosition, T::kU2, kMrad, kFt, expand({zx_y, zy_x}, s12)});
  add("4.2", "1&2 | ζ_z | U3", {K::kPosition, T::kU3, kMrad, kFt, expand({zz_x}, s12)});
  add("4.2", "1 | (u)ψ | U3", {K::kPosition, T::kU3, kMrad, kFt, expand({upsi}, s1)});
  add("4.2", "1&2 | δV(0)_k, k = x, y, z | U3",
      {K::kPosition, T::kDV, kFtpsToMps, kFt, expand({vx, vy, vz}, s12)});
  add("4.2", "1&2 | δh | U2",
      {K::kPosition, T::kU2, kFt, kFt, expand({{"δh", uncertainty_slot::kAltitudeError, Z}}, s12)});

  // ---- Table 5.1: after scheme 5.1.1 and realignment, (5.4): residual
  // coefficients per unit, and the unchanged U4, U5 of (3.29d, e).
  add("5.1", "δV(0)_k, k=x,y,z | δV(0)", {K::kCoefficient, T::kDV, kFtpsToMps, kFt, {{"", System::kTheodolite, X, 0}}});
  add("5.1", "U'2k, k=x,y,z | U'2", {K::kCoefficient, T::kU2, 1e-4, kFt, {{"", System::kTheodolite, X, 0}}});
  add("5.1", "U'3k, k=x,y,z | U'3", {K::kCoefficient, T::kU3, 1e-3, kFt, {{"", System::kTheodolite, X, 0}}});
  add("5.1", "ω_dok, k=x,z | U'4",
      {K::kPosition, T::kU4, kMeru, kFt, expand({{"ω_dox", uncertainty_slot::kGyroDrift + 0, Z}, wdz_x}, s12)});
  add("5.1", "gMUY_k, k=x,y | U'4", {K::kPosition, T::kU4, kMeru, kFt, expand({mux_y, muy_x}, s12)});
  add("5.1", "ω_doy(2) | U'4", {K::kPosition, T::kU4, kMeru, kFt, expand({wdy_y}, s2)});
  add("5.1", "ω_doz | U'5",
      {K::kPosition, T::kU5, kMeru, kFt, expand({{"ω_doz", uncertainty_slot::kGyroDrift + 2, Y}}, s12)});
  add("5.1", "gMUY_z | U'5", {K::kPosition, T::kU5, kMeru, kFt, expand({muz_x}, s12)});

  // ---- Table 5.2: scheme 5.4 (alignment data only), (3.29) with U'2 (5.20), U'3..U'5 (5.17a–c).
  const Maps m54 = Maps::kScheme54;
  const Reference paper_maps = Reference::kPaperMaps;
  add("5.2", "δV(0)_k, k = x, y, z", {K::kCoefficient, T::kDV, kFtpsToMps, kFt, {{"", System::kTheodolite, X, 0}}});
  // δf_x, δf_y do not enter U'2 (5.20): the row means ∂f_x, ∂f_y.
  add("5.2", "δf_k, k = x, y, δg",
      {K::kPosition, T::kU2, kUg, kFt,
       expand({{"∂f_x (printed δf_x)", pfx.column, X}, {"∂f_y (printed δf_y)", pfy.column, Y},
               {"δg", map_column::kGravityError, Z}},
              s12),
       m54, paper_maps});
  add("5.2", "Δζ_k, k = x, y",
      {K::kPosition, T::kU2, kUrad, kFt,
       expand({{"Δζ_x = ζ_rx", uncertainty_slot::kMisalignAlign + 0, Y}, {"Δζ_y = ζ_ry", uncertainty_slot::kMisalignAlign + 1, X}}, s12),
       m54, paper_maps});
  add("5.2", "δf_k, k = x, y",
      {K::kPosition, T::kU3, kMg, kFt, expand({{"δf_x", dfx.column, Y}, {"δf_y", dfy.column, X}}, s12), m54,
       paper_maps});
  {
    std::vector<Member> zeta = expand({{"ζ_cx", uncertainty_slot::kMisalignConst + 0, X}, {"ζ_cy", uncertainty_slot::kMisalignConst + 1, Y},
                                       {"ζ_rx", uncertainty_slot::kMisalignAlign + 0, Z}, {"ζ_rz", uncertainty_slot::kMisalignAlign + 2, X}},
                                      s1);
    for (auto& m : zeta) m.label += ", sys 1";
    std::vector<Member> zeta2 = expand({{"ζ_cx", uncertainty_slot::kMisalignConst + 0, X}, {"ζ_cy", uncertainty_slot::kMisalignConst + 1, Y},
                                        {"ζ_cz", uncertainty_slot::kMisalignConst + 2, X}, {"ζ_rx", uncertainty_slot::kMisalignAlign + 0, X},
                                        {"ζ_rz", uncertainty_slot::kMisalignAlign + 2, X}},
                                       s2);
    for (auto& m : zeta2) m.label += ", sys 2";
    zeta.insert(zeta.end(), zeta2.begin(), zeta2.end());
    add("5.2", "ζ_k, ζ_ck, ζ_rk, k = x, y, z", {K::kPosition, T::kU3, kMrad, kFt, zeta, m54, paper_maps});
  }
  {
    std::vector<Member> eps = expand({{"ε4x", map_column::kEps4 + 0, Y}}, s12);
    std::vector<Member> eps_y = expand({{"ε4y", map_column::kEps4 + 1, X}}, s1);
    eps_y[0].label = "ε4y, sys 1";
    eps.insert(eps.end(), eps_y.begin(), eps_y.end());
    add("5.2", "ε4x, ε4y(1)", {K::kPosition, T::kU3, 1e-4, kFt, eps, m54, paper_maps});
  }
  add("5.2", "gMUY_k, k = x, y", {K::kPosition, T::kU4, kMeru, kFt, expand({mux_y, muy_x}, s12), m54});
  add("5.2", "ω_doy(2)", {K::kPosition, T::kU4, kMeru, kFt, expand({wdy_y}, s2), m54});
  add("5.2", "ε4z", {K::kPosition, T::kU4, 1e-4, kFt, expand({{"ε4z", map_column::kEps4 + 2, X}}, s12), m54, paper_maps});
  add("5.2", "gMUY_z", {K::kPosition, T::kU5, kMeru, kFt, expand({muz_x}, s12), m54});
  return s;
}

// ---- the model at both levels --------------------------------------------------

/// The linear model of one system with the Taylor coefficients of its
/// forcing at t = 0: u(t) = u0 + u1 t + u2 t²/2 + … (u0 = g K1, u1 = g ω_ie U3,
/// u2 = g ω_ie² U4 at the paper level).
struct LinearTerms {
  std::unique_ptr<LinearErrorModel> model;
  Sensitivity3 u0, u1, u2;
};

class Evaluator {
 public:
  Evaluator(const ModelOptions& o, TableConvention c, std::vector<double> ode_times_s)
      : o_(o), c_(c), ode_times_s_(std::move(ode_times_s)) {}

  const ModelOptions& options() const { return o_; }
  TableConvention convention() const { return c_; }

  /// The signed value of `member` of a row at time t [s], in the row's unit.
  double value(const RowSpec& spec, const Member& member, double t) {
    double v = 0.0;
    const bool linear = c_ == TableConvention::kCorrected && spec.corrected == Reference::kLinear &&
                        spec.kind != Kind::kCoefficient && member.column < uncertainty_slot::kDim;
    if (spec.kind == Kind::kCoefficient) {
      v = position_time_function(spec.term, t);
    } else if (linear) {
      v = linear_value(spec, member, t);
    } else {
      const ExtendedMap map = paper_map(spec, member.system);
      const double c = map(member.axis, member.column);
      v = spec.kind == Kind::kAccel ? o_.gravity_mps2 * c * accel_time_function(spec.term, t)
                                    : c * position_time_function(spec.term, t);
    }
    return v * spec.per_unit_si / spec.out_unit_si;
  }

  /// U4 per unit of an uncertainty on an axis (the (4.6) thresholds after Table 4.3).
  double u4_coefficient(System sys, int axis, int column) {
    if (c_ == TableConvention::kCorrected) {
      const LinearTerms& l = linear(sys);
      const double w = o_.earth_rate_radps;
      return l.u2(axis, column) / (o_.gravity_mps2 * w * w);
    }
    return paper(sys).u4(axis, column);
  }

 private:
  /// 1, ω_ie t, ½(ω_ie t)², (ω_ie t)³/6: the time functions of (4.4) (U5: the next term of (4.3)).
  double accel_time_function(Term term, double t) const {
    const double p = o_.earth_rate_radps * t;
    switch (term) {
      case Term::kA1: return 1.0;
      case Term::kU3: return p;
      case Term::kU4: return 0.5 * p * p;
      case Term::kU5: return p * p * p / 6.0;
      default: throw std::logic_error("no accelerometer time function for this term");
    }
  }

  /// sin(ω_s t)/ω_s [s] for δV(0); r0 × the (3.29) functions for U2..U5 [m];
  /// kCorrected takes U5's from (3.30).
  double position_time_function(Term term, double t) const {
    const ShortRunFunctions f = short_run_functions_3_29(t, o_);
    const double r0 = o_.radius_m;
    switch (term) {
      case Term::kDV: return f.initial_velocity_s;
      case Term::kU2: return r0 * f.u2;
      case Term::kU3: return r0 * f.u3;
      case Term::kU4: return r0 * f.u4;
      case Term::kU5: return r0 * (c_ == TableConvention::kCorrected ? u5_function_3_30(t, o_) : f.u5);
      default: throw std::logic_error("no position time function for this term");
    }
  }

  ExtendedMap paper_map(const RowSpec& spec, System sys) {
    if (spec.maps == Maps::kScheme54) {
      const ResidualMatrices& r = scheme54(sys);
      switch (spec.term) {
        case Term::kU2: return r.u2;
        case Term::kU3: return r.u3;
        case Term::kU4: return r.u4;
        case Term::kU5: return r.u5;
        default: throw std::logic_error("scheme 5.4 has no such residual matrix");
      }
    }
    const ShortRunMatrices& m = paper(sys);
    switch (spec.term) {
      case Term::kA1: {
        // (4.4b) A1 = U2 + δr(0)/r0, and (4.3a): δg/g in A1_z.
        ExtendedMap a1 = extend(paper_a1(m, o_));
        a1(Z, map_column::kGravityError) = 1.0 / o_.gravity_mps2;
        return a1;
      }
      case Term::kU2: return extend(m.u2);
      case Term::kU3: return extend(m.u3);
      case Term::kU4: return extend(m.u4);
      case Term::kU5: return extend(m.u5);
      case Term::kDV: return extend(m.initial_velocity_mps);
    }
    throw std::logic_error("unknown term");
  }

  /// kCorrected, linear reference. Accelerometer rows: A1 = the constant part
  /// u0 of the forcing (= Δf^a (4.2)); U3, U4 rows = the forcing less its
  /// Taylor terms below order 1, 2. Position rows (Δr = δr − δr(0)): U2 =
  /// the response to u0 and δr(0); δV = the response to δV(0); U3..U5 = the
  /// Schuler-ODE response to the forcing less its Taylor terms below order
  /// 1..3, i.e. the exact, untruncated effect of that part.
  double linear_value(const RowSpec& spec, const Member& m, double t) {
    const LinearTerms& l = linear(m.system);
    const int a = m.axis, col = m.column;
    if (spec.kind == Kind::kAccel) {
      switch (spec.term) {
        case Term::kA1: return l.u0(a, col);
        case Term::kU3: return l.model->forcing(t)(a, col) - l.u0(a, col);
        case Term::kU4: return l.model->forcing(t)(a, col) - l.u0(a, col) - l.u1(a, col) * t;
        default: throw std::logic_error("no linear accelerometer term");
      }
    }
    const double ws = o_.schuler_radps();
    switch (spec.term) {
      case Term::kDV: return l.model->initial_velocity()(a, col) * std::sin(ws * t) / ws;
      case Term::kU2:
        return (l.u0(a, col) / (ws * ws) - l.model->initial_position()(a, col)) * (1.0 - std::cos(ws * t));
      case Term::kU3: return remainder(m.system, 1, t)(a, col);
      case Term::kU4: return remainder(m.system, 2, t)(a, col);
      case Term::kU5: return remainder(m.system, 3, t)(a, col);
      default: throw std::logic_error("no linear position term");
    }
  }

  const ShortRunMatrices& paper(System sys) {
    auto& slot = paper_[system_number(sys)];
    if (!slot) slot = paper_short_run_matrices(sys, o_);
    return *slot;
  }

  const ResidualMatrices& scheme54(System sys) {
    auto& slot = scheme54_[system_number(sys)];
    if (!slot) slot = alignment_data_residuals(sys, o_, c_ == TableConvention::kCorrected);
    return *slot;
  }

  const LinearTerms& linear(System sys) {
    auto& slot = linear_[system_number(sys)];
    if (!slot.model) {
      slot.model = std::make_unique<LinearErrorModel>(sys, o_);
      const double h = kTaylorStepS;
      const Sensitivity3 fm2 = slot.model->forcing(-2 * h), fm1 = slot.model->forcing(-h),
                         f0 = slot.model->forcing(0.0), fp1 = slot.model->forcing(h),
                         fp2 = slot.model->forcing(2 * h);
      slot.u0 = f0;
      slot.u1 = (fm2 - 8.0 * fm1 + 8.0 * fp1 - fp2) / (12.0 * h);
      slot.u2 = (-fm2 + 16.0 * fm1 - 30.0 * f0 + 16.0 * fp1 - fp2) / (12.0 * h * h);
    }
    return slot;
  }

  /// Response of δr̈ + ω_s² δr = u(t) − Σ_{k<order} u_k t^k/k!, δr(0) = δṙ(0) = 0.
  const Sensitivity3& remainder(System sys, int order, double t) {
    auto& slot = remainder_[{system_number(sys), order}];
    if (slot.empty()) {
      const LinearTerms& l = linear(sys);
      auto forcing = [&l, order](double tau) {
        Sensitivity3 u = l.model->forcing(tau) - l.u0;
        if (order >= 2) u -= tau * l.u1;
        if (order >= 3) u -= (0.5 * tau * tau) * l.u2;
        return u;
      };
      const std::vector<Sensitivity3> maps = integrate_schuler_ode(
          forcing, Sensitivity3::Zero(), Sensitivity3::Zero(), ode_times_s_, o_.schuler_radps(), kOdeMaxStepS);
      for (std::size_t i = 0; i < maps.size(); ++i) slot.emplace(ode_times_s_[i], maps[i]);
    }
    const auto it = slot.find(t);
    if (it == slot.end()) throw std::logic_error(fmt::format("no ODE time {} s prepared", t));
    return it->second;
  }

  ModelOptions o_;
  TableConvention c_;
  std::vector<double> ode_times_s_;
  std::map<int, std::optional<ShortRunMatrices>> paper_;
  std::map<int, std::optional<ResidualMatrices>> scheme54_;
  std::map<int, LinearTerms> linear_;
  std::map<std::pair<int, int>, std::map<double, Sensitivity3>> remainder_;
};

// ---- Table 3.1, 4.3, 4.3b -------------------------------------------------------

/// SI size of a Table 3.1 unit.
double unit_si(std::string_view unit) {
  if (unit == "mg") return kMg;
  if (unit == "1") return 1.0;
  if (unit == "%") return 0.01;
  if (unit == "meru") return kMeru;
  if (unit == "mrad") return kMrad;
  if (unit == "arcmin") return kArcminToRad;
  if (unit == "arcsec") return kArcsecToRad;
  if (unit == "m/s" || unit == "m") return 1.0;
  if (unit == "ft/s") return kFtpsToMps;
  if (unit == "deg") return kDegToRad;
  throw std::logic_error(fmt::format("Table 3.1 unit '{}' unknown", unit));
}

/// A member of a non-generic row: its label and its value as a function of
/// the column time [s] (ignored where the column is not a time).
struct MemberFn {
  std::string label;
  std::function<double(double)> value;
};

std::vector<MemberFn> table_3_1_members(const std::string& row, const ModelOptions& o) {
  const UncertaintyVector b = default_bounds();
  auto one = [&b](std::string label, std::vector<int> columns) {
    return MemberFn{std::move(label), [b, columns](double) {
                      double v = 0.0;
                      for (int c : columns) v += b[c];  // ζ = ζ_c + ζ_r, ∂f = ∂f_c + ∂f_r (catalogue.cpp)
                      return v;
                    }};
  };
  auto xyz = [&one](std::string sym, int base) {
    return std::vector<MemberFn>{one(sym + "x", {base}), one(sym + "y", {base + 1}), one(sym + "z", {base + 2})};
  };
  if (row == "Accelerometer bias δf_k") return xyz("δf_", uncertainty_slot::kAccelBias);
  if (row == "Accelerometer scale factor a_k") return xyz("a_", uncertainty_slot::kAccelScale);
  if (row == "Accelerometer bias change ∂f_x, ∂f_y")
    return {one("∂f_x = ∂f_cx + ∂f_rx", {uncertainty_slot::kBiasChangeConst + 0, uncertainty_slot::kBiasChangeAlign + 0}),
            one("∂f_y = ∂f_cy + ∂f_ry", {uncertainty_slot::kBiasChangeConst + 1, uncertainty_slot::kBiasChangeAlign + 1})};
  if (row == "Fixed drift rate ω_dok") return xyz("ω_do", uncertainty_slot::kGyroDrift);
  if (row == "Mass unbalance ω_MUk") return xyz("ω_MU", uncertainty_slot::kGyroMuDrift);
  if (row == "g·MUY_k") return xyz("g·MUY_", uncertainty_slot::kGyroMuyDrift);
  if (row == "Alignment caused by x and y gyro drift") {
    // ψ_ωk(1) = ω_dok/F(0) (2.17c) at the drift bound; system 2 has ψ_ωx = ψ_ωy = 0.
    const double f0 = o.leveling_gain_ratio * o.earth_rate_radps;
    return {MemberFn{"ψ_ωx = ω_dox/F(0)", [b, f0](double) { return b[uncertainty_slot::kGyroDrift + 0] / f0; }},
            MemberFn{"ψ_ωy = ω_doy/F(0)", [b, f0](double) { return b[uncertainty_slot::kGyroDrift + 1] / f0; }}};
  }
  if (row == "Misalignment ζ_k, (u)ψ")
    return {one("ζ_x = ζ_cx + ζ_rx", {uncertainty_slot::kMisalignConst + 0, uncertainty_slot::kMisalignAlign + 0}),
            one("ζ_y = ζ_cy + ζ_ry", {uncertainty_slot::kMisalignConst + 1, uncertainty_slot::kMisalignAlign + 1}),
            one("ζ_z = ζ_cz + ζ_rz", {uncertainty_slot::kMisalignConst + 2, uncertainty_slot::kMisalignAlign + 2}),
            one("(u)ψ", {uncertainty_slot::kTheodolite})};
  if (row == "Deflection of the vertical ξ, η")
    return {one("ξ", {uncertainty_slot::kDeflection + 0}), one("η", {uncertainty_slot::kDeflection + 1})};
  if (row == "Initial velocity δV(0)_k") return xyz("δV(0)_", uncertainty_slot::kInitialVelocity);
  if (row == "Latitude error δL_0") return {one("", {uncertainty_slot::kLatitudeError})};
  if (row == "Altitude error δh") return {one("", {uncertainty_slot::kAltitudeError})};
  if (row == "Latitude L_0") return {MemberFn{"", [lat = o.latitude_rad](double) { return lat; }}};
  throw std::logic_error("Table 3.1 row without a specification: " + row);
}

std::vector<MemberFn> table_4_3_members(const PrintedCell& cell, Evaluator& ev) {
  const ModelOptions& o = ev.options();
  const double dv = kTable43PulseWeightFtps * kFtToM;
  if (cell.table == "4.3") {
    int which = cell.row == "A1k" ? 0 : cell.row == "U3k" ? 1 : cell.row == "U4k" ? 2 : -1;
    if (which < 0) throw std::logic_error("Table 4.3 row without a specification: " + cell.row);
    return {MemberFn{"", [dv, which, o](double T) {
                       const ResolutionLimits r = pulse_resolution_limits(dv, T, o);  // (4.6)
                       return which == 0 ? r.a1 : which == 1 ? r.u3 : r.u4;
                     }}};
  }
  // 4.3b: the drift that makes its U4 term reach the U4 threshold of (4.6):
  // |U4 per meru| × drift ≥ 18ΔV/(ω_ie² T³ g).
  struct Probe {
    std::string label;
    System sys;
    int axis, column;
  };
  std::vector<Probe> probes;
  if (cell.row == "gMUY_x, gMUY_y") {
    for (System s : {System::kTheodolite, System::kGyrocompass}) {
      const int n = system_number(s);
      probes.push_back({fmt::format("gMUY_x, sys {}", n), s, Y, uncertainty_slot::kGyroMuyDrift + 0});
      probes.push_back({fmt::format("gMUY_y, sys {}", n), s, X, uncertainty_slot::kGyroMuyDrift + 1});
    }
  } else if (cell.row == "ω_doz") {
    for (System s : {System::kTheodolite, System::kGyrocompass})
      probes.push_back({fmt::format("ω_doz, sys {}", system_number(s)), s, X, uncertainty_slot::kGyroDrift + 2});
  } else {
    throw std::logic_error("Table 4.3b row without a specification: " + cell.row);
  }
  std::vector<MemberFn> out;
  for (const Probe& p : probes) {
    const double per_meru = std::abs(ev.u4_coefficient(p.sys, p.axis, p.column)) * kMeru;
    out.push_back({p.label, [dv, o, per_meru](double T) {
                     return pulse_resolution_limits(dv, T, o).u4 / per_meru;  // meru
                   }});
  }
  return out;
}

// ---- notes ------------------------------------------------------------------------

bool note_applies(const CellNote& n, const std::string& table, const std::string& row,
                  const std::string& column, TableConvention c) {
  if (n.table != table) return false;
  if (n.row != row && n.row != printed_row_key(row)) return false;
  if (n.column != "*" && n.column != column) return false;
  if (n.scope == NoteScope::kPaper && c != TableConvention::kPaper) return false;
  if (n.scope == NoteScope::kCorrected && c != TableConvention::kCorrected) return false;
  return true;
}

double minutes_of(const std::string& column) {
  const auto pos = column.find(" min");
  if (pos == std::string::npos) return std::nan("");
  return std::stod(column.substr(0, pos));
}

std::string format_value(double v) { return fmt::format("{:.4g}", v); }

constexpr std::string_view kNoteKinds[] = {"rounding",   "ocr",        "paper_slip",       "paper_approximation",
                                           "time_shift", "paper_error", "model_difference", "label",
                                           "zero"};

bool scope_matches(const CellNote& n, TableConvention c) {
  return n.scope == NoteScope::kBoth || (n.scope == NoteScope::kPaper && c == TableConvention::kPaper) ||
         (n.scope == NoteScope::kCorrected && c == TableConvention::kCorrected);
}

std::vector<TableCell> run(const ModelOptions& options, TableConvention convention,
                           std::vector<NoteCheck>* checks) {
  const auto& printed = printed_cells();
  const auto& notes = cell_notes();
  // Every time the Schuler ODE must reach: the printed columns and the
  // notes' alternative times.
  std::vector<double> times;
  for (const auto& p : printed) {
    const double m = minutes_of(p.column);
    if (!std::isnan(m)) times.push_back(m * kMinToS);
  }
  for (const auto& n : notes)
    if (n.alt_time_min) times.push_back(*n.alt_time_min * kMinToS);
  std::sort(times.begin(), times.end());
  times.erase(std::unique(times.begin(), times.end()), times.end());

  Evaluator ev(options, convention, times);
  const auto specs = row_specs(options);
  std::vector<bool> note_used(notes.size(), false);

  std::vector<TableCell> out;
  for (const auto& p : printed) {
    std::vector<MemberFn> members;
    double out_factor = 1.0;  // SI → printed unit for tables whose functions return SI
    if (p.table == "3.1") {
      members = table_3_1_members(p.row, options);
      out_factor = 1.0 / unit_si(p.unit);
    } else if (p.table == "4.3" || p.table == "4.3b") {
      members = table_4_3_members(p, ev);
    } else {
      const auto it = specs.find({p.table, p.row});
      if (it == specs.end())
        throw std::logic_error(fmt::format("Table {} row '{}' has no specification", p.table, p.row));
      const RowSpec* spec = &it->second;
      for (const Member& m : spec->members)
        members.push_back({m.label, [&ev, spec, m](double t) { return ev.value(*spec, m, t); }});
    }
    const double t_min = minutes_of(p.column);
    for (const MemberFn& m : members) {
      TableCell cell;
      cell.table = p.table;
      cell.row = m.label.empty() ? p.row : fmt::format("{} [{}]", p.row, m.label);
      cell.column = p.column;
      cell.unit = p.unit;
      cell.printed = p.printed;
      cell.computed = std::abs(m.value(t_min * kMinToS) * out_factor);
      if (p.printed != 0.0) cell.deviation_pct = 100.0 * (cell.computed - p.printed) / p.printed;
      std::string text;
      for (std::size_t k = 0; k < notes.size(); ++k) {
        const CellNote& n = notes[k];
        if (!note_applies(n, cell.table, cell.row, cell.column, convention)) continue;
        note_used[k] = true;
        auto check = [&](bool holds, std::string detail) {
          if (checks) checks->push_back({cell.table, cell.row, cell.column, n.kind, holds, std::move(detail)});
        };
        check(std::find(std::begin(kNoteKinds), std::end(kNoteKinds), n.kind) != std::end(kNoteKinds),
              "kind " + n.kind);
        std::string part = n.text;
        if (n.kind == "rounding") {
          const double half = half_unit_in_last_place(p.printed_text);
          const double diff = std::abs(cell.computed - p.printed);
          check(diff <= half * (1.0 + 1e-9),
                fmt::format("|{} − {}| = {} vs half a unit in the last place {}", format_value(cell.computed),
                            p.printed_text, format_value(diff), format_value(half)));
        }
        if (n.meant) {
          const double dev = 100.0 * (cell.computed - *n.meant) / *n.meant;
          part += fmt::format(" [meant {}; computed {:+.1f}% from it]", format_value(*n.meant), dev);
          check(std::abs(dev) <= kNoteThresholdPct,
                fmt::format("computed {} vs meant {}: {:+.2f}%", format_value(cell.computed),
                            format_value(*n.meant), dev));
        }
        if (n.alt_time_min) {
          const double alt = std::abs(m.value(*n.alt_time_min * kMinToS) * out_factor);
          const double dev = 100.0 * (alt - p.printed) / p.printed;
          part += fmt::format(" [computed at {} min: {}, {:+.1f}% from printed]", format_value(*n.alt_time_min),
                              format_value(alt), dev);
          check(std::abs(dev) <= kNoteThresholdPct,
                fmt::format("computed at {} min {} vs printed {}: {:+.2f}%", format_value(*n.alt_time_min),
                            format_value(alt), p.printed_text, dev));
        }
        if (!text.empty()) text += " | ";
        text += n.kind + ": " + part;
      }
      cell.note = std::move(text);
      out.push_back(std::move(cell));
    }
  }

  // Figure 3.2: the (3.29) terms per unit (kCorrected: U5 from (3.30)).
  struct Curve {
    const char* row;
    const char* unit;
    Term term;
    double per_unit;
  };
  const Curve curves[] = {{"δV(0) per ft/s", "ft/(ft/s)", Term::kDV, kFtpsToMps},
                          {"U2 per 1e-4", "ft/1e-4", Term::kU2, 1e-4},
                          {"U3 per 1e-3", "ft/1e-3", Term::kU3, 1e-3},
                          {"U4 per 1e-3 (1 meru of g·MUY_y)", "ft/1e-3", Term::kU4, 1e-3},
                          {"U5 per 1e-3", "ft/1e-3", Term::kU5, 1e-3}};
  for (const Curve& c : curves) {
    const RowSpec spec{Kind::kCoefficient, c.term, c.per_unit, kFt, {}};
    const Member none{"", System::kTheodolite, X, 0};
    for (double m = 0.0; m <= kFigureEndMin + 1e-9; m += kFigureStepMin) {
      TableCell cell;
      cell.table = "fig3.2";
      cell.row = c.row;
      cell.column = fmt::format("{:g} min", m);
      cell.time_min = m;
      cell.unit = c.unit;
      cell.computed = ev.value(spec, none, m * kMinToS);
      out.push_back(std::move(cell));
    }
  }
  if (checks) {
    for (std::size_t k = 0; k < notes.size(); ++k)
      if (scope_matches(notes[k], convention) && !note_used[k])
        checks->push_back({notes[k].table, notes[k].row, notes[k].column, notes[k].kind, false,
                           "the note matches no cell"});
  }
  return out;
}

}  // namespace

std::vector<TableCell> compute_tables(const ModelOptions& options, TableConvention convention) {
  return run(options, convention, nullptr);
}

std::vector<NoteCheck> check_note_claims(const ModelOptions& options, TableConvention convention) {
  std::vector<NoteCheck> checks;
  run(options, convention, &checks);
  return checks;
}

}  // namespace insmc::tables
