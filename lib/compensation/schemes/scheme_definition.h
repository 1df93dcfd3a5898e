#pragma once
/// One compensation scheme of chapter 5, defined once (one file each in this
/// folder, listed in registry.cpp): its name and equations, the traits every
/// other part of insmc asks for (clock, realignment, resets, the data it
/// uses), the catalogue groups of the measurement errors it relies on, and
/// how it acts at each fidelity through the injection points of fig. 5.1:
///   * paper and linear levels (`position_map`): the columns it adds to the
///     position error's map of z (extended_vector.h) at one time on its
///     clock, given the uncompensated map there;
///   * truth level (`truth_action`): the compensation it sets on the truth
///     simulator from what the test run and the alignment phase measured.
/// The machinery the traits switch on (a realignment's fresh draws, the
/// resets at T and their propagation, the torquer response, the alignment
/// measurements of the truth) is shared and lives in compensation_maps.cpp
/// and truth_compensation.cpp. These files need headers only: the record
/// readers know the schemes by name without the physics library.
#include <cmath>
#include <string_view>
#include <vector>

#include "lib/common/model_options.h"
#include "lib/common/system.h"
#include "lib/frames/frames.h"
#include "lib/compensation/extended_vector.h"
#include "lib/preflight/test_run_estimates.h"
#include "lib/propagation/closed_form.h"
#include "lib/truth/simulator.h"

namespace insmc {

/// The closed forms of the paper level's schemes: as the report prints
/// them, (5.9) and (5.11b) restarting the U5 growth at the reset and (5.20)
/// with +δg (tables/notes/errata.md#5-9, #5-20), or corrected, derived from
/// (5.8) and (5.19) (what the linear level integrates). The paper level
/// means the printed forms; the corrected ones exist for the term-by-term
/// check of the errata.
enum class SchemeForms { kPrinted, kCorrected };

/// What a scheme's position map is built from at one time τ on its clock.
struct SchemeMapContext {
  System system;
  Fidelity fidelity;
  SchemeForms forms;
  const ModelOptions& model;
  double test_duration_s;
  double tau_s;
  /// δr per unit x at τ before the scheme's own terms: after the resets at T
  /// for a scheme that resets, from the (re)alignment otherwise.
  const Sensitivity3& uncompensated;
  /// δr per unit torquer rate applied from t = 0 in the navigation mode
  /// (point 4); computed for schemes that use the alignment data, else zero.
  const Mat3& torquer_response;
  /// The time functions of (3.29) at τ (paper level; zero at the linear).
  const ShortRunFunctions& paper_functions;
};

/// What a truth-level scheme acts on: the test run's estimates and, for a
/// scheme that uses them, the alignment phase's counted measurements.
struct TruthSchemeContext {
  System system;
  const ModelOptions& model;
  double test_duration_s;
  const TestRunEstimates& estimates;
  Vec3 alignment_commands_radps = Vec3::Zero();  ///< ω_c of (5.14), less ω_ie, as counted
  Vec3 alignment_accel_mps2 = Vec3::Zero();      ///< Δf_m of (5.18), less g, as counted
};

/// Adds the scheme's terms to `e`, the map of z at τ (already holding the
/// uncompensated map, with a realignment's fresh draws in their z slots).
using PositionMapFn = void (*)(const SchemeMapContext& context, ExtendedMap& e);
/// Sets the scheme's compensation on the truth options `o` (points 2, 4)
/// and on the sample's uncertainties `x` where the scheme acts like a change
/// of them (torquer rates through a realignment act as a drift change).
using TruthActionFn = void (*)(const TruthSchemeContext& context, TruthOptions& o, UncertaintyVector& x);

struct SchemeDefinition {
  /// The one spelling used in options and files ("5.1.1").
  std::string_view name;
  /// The report's equations the scheme implements.
  std::string_view equations;
  /// A realignment after the test run (fresh ζ_r, ∂f_r, (u)V, then a new
  /// switch-over, where the scheme's clock starts).
  bool realigns = false;
  /// The velocity and position integrators are reset at the test's end T
  /// (points 5, 6), where the scheme's clock starts.
  bool resets_at_test_end = false;
  /// Needs the preflight test run's estimates.
  bool uses_test_run = false;
  /// Needs the alignment phase's torquer commands and accelerometer outputs.
  bool uses_alignment_data = false;
  /// Catalogue groups (catalogue.h) of the measurement errors the scheme
  /// relies on; each also in the group `scheme_errors`.
  std::vector<std::string_view> measurement_error_groups = {};
  PositionMapFn position_map = nullptr;
  TruthActionFn truth_action = nullptr;
};

namespace scheme_terms {

// Responses of the Schuler loop ÿ + ω_s² y = a(τ) from rest to a unit step
// and a unit ramp τ (Laplace pairs of fig. 3.3).
inline double step_response(double tau, double ws) { return (1 - std::cos(ws * tau)) / (ws * ws); }
inline double ramp_response(double tau, double ws) { return (tau - std::sin(ws * tau) / ws) / (ws * ws); }

/// Torquer compensation rates ω_cp (point 4) per unit of Û3 (5.5a, b):
/// ω_ie[Û3y; −Û3x; 0] for system 1, ω_ie[Û3y; 0; 0] for system 2.
inline Mat3 torquer_rates_from_u3(System system, const ModelOptions& m) {
  Mat3 t = Mat3::Zero();
  t(0, 1) = m.earth_rate_radps;  // ω_cp,x = ω_ie Û3y
  if (system == System::kTheodolite) t(1, 0) = -m.earth_rate_radps;  // ω_cp,y = −ω_ie Û3x (5.5a)
  return t;
}

/// Which Û3 components go through integrators to point 2 in `combined`
/// (end of 5.1.2): z for system 1; x and z for system 2.
inline Mat3 combined_integrator_selection(System system) {
  Mat3 s = Mat3::Zero();
  s(2, 2) = 1;
  if (system == System::kGyrocompass) s(0, 0) = 1;
  return s;
}

/// The step Û2 of 5.1.x at point 2 (5.2), (5.5): −g Û2, as a map.
inline void add_u2_step(const SchemeMapContext& c, ExtendedMap& e) {
  const double g = c.model.gravity_mps2, ws = c.model.schuler_radps();
  e.middleCols<3>(z_slot::kU2) = -g * step_response(c.tau_s, ws) * Mat3::Identity();
}

/// Û3 through integrators into point 2 (5.3), (5.11): the ramp −g ω_ie Û3 τ,
/// per unit of Û3 on each axis it is applied to.
inline double u3_ramp_per_unit(const SchemeMapContext& c) {
  return -c.model.gravity_mps2 * c.model.earth_rate_radps * ramp_response(c.tau_s, c.model.schuler_radps());
}

/// 5.1.2's Û3 to the gyro torquers (5.5) as a map: the rates ω_cp act
/// through the realignment and after it, as a change of the level-platform
/// drift ω_do, so they enter through the drift's own columns.
inline Mat3 u3_to_torquers(const SchemeMapContext& c) {
  return c.uncompensated.middleCols<3>(uncertainty_slot::kGyroDrift) * torquer_rates_from_u3(c.system, c.model);
}

/// The same at the truth level: ω_cp added to the sample's drift (5.5).
inline void apply_u3_to_torquers(const TruthSchemeContext& c, UncertaintyVector& x) {
  x.segment<3>(uncertainty_slot::kGyroDrift) += torquer_rates_from_u3(c.system, c.model) * c.estimates.u3;
}

}  // namespace scheme_terms
}  // namespace insmc
