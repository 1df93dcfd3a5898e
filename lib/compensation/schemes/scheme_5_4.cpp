#include "lib/compensation/schemes/schemes.h"

namespace insmc::schemes {
namespace {

/// (5.15c): system 2 has no y estimate of the drift.
Mat3 estimated_axes(System system) {
  Mat3 select = Mat3::Identity();
  if (system == System::kGyrocompass) select(1, 1) = 0;
  return select;
}

}  // namespace

/// 5.4: the alignment phase's data only. The measured torquer commands
/// (5.14), less earth rate, go to the torquers from t = 0 (5.15), (5.16);
/// the measured accelerometer outputs (5.18) to point 2 (5.19). Its
/// drift-estimate error ω_ie E4 of (5.15), (5.15a) is the catalogue's
/// alignment_drift_error.
const SchemeDefinition& scheme_5_4() {
  static const SchemeDefinition d{
      .name = "5.4",
      .equations = "(5.13)-(5.21)",
      .uses_alignment_data = true,
      .measurement_error_groups = {"alignment_drift_error"},
      .position_map =
          [](const SchemeMapContext& c, ExtendedMap& e) {
            const Mat3 applied = c.torquer_response * estimated_axes(c.system);
            e.middleCols<3>(z_slot::kTorquerCommands) = applied;
            e.middleCols<3>(uncertainty_slot::kAlignDriftError) = applied;  // E4 enters the rates as the commands do
            const double ws = c.model.schuler_radps();
            e.middleCols<3>(z_slot::kAlignAccel) = -scheme_terms::step_response(c.tau_s, ws) * Mat3::Identity();
            // (5.20) as printed: U'2_z = δg − 2δh/r0, where −Δf_m/g at point 2 gives
            // −δg/g − 2δh/r0; with δg/g = −3δh/r0 (§4.1) the printed z row is
            // −5δh/r0 against the derived +δh/r0 (errata.md#5-20). (ε5's sign, the
            // other difference, is immaterial: a zero-mean measurement error.)
            if (c.fidelity == Fidelity::kPaper && c.forms == SchemeForms::kPrinted) {
              e(2, uncertainty_slot::kAltitudeError) += -6.0 * (1 - std::cos(ws * c.tau_s));  // r0 (−6δh/r0)(1 − cos ω_s t)
              // (5.17b) as printed: U'4_z = −2 cos L0 C_y cos L0 where (3.29d) with
              // (5.16a) gives −2 cos L0 C_y sin L0 (errata.md#5-17b), C_y taken as
              // printed, −δf_x/g + ζ_cy; through r0 (ω_ie/ω_s)²[½ ω_s² t² − (1 − cos ω_s t)].
              const double L = c.model.latitude_rad;
              const double per_cy = c.model.radius_m * c.paper_functions.u4 * -2 * std::cos(L) *
                                    (std::cos(L) - std::sin(L));
              e(2, uncertainty_slot::kAccelBias + 0) += -per_cy / c.model.gravity_mps2;
              e(2, uncertainty_slot::kMisalignConst + 1) += per_cy;  // ζ_r enters after the commands measured C
            }
          },
      .truth_action =
          [](const TruthSchemeContext& c, TruthOptions& o, UncertaintyVector& x) {
            const Vec3 commands = estimated_axes(c.system) * (c.alignment_commands_radps + x.segment<3>(uncertainty_slot::kAlignDriftError));
            o.torquer_command_radps = [commands](double) { return commands; };
            o.accel_compensation.step_mps2 = -c.alignment_accel_mps2;
          },
  };
  return d;
}

}  // namespace insmc::schemes
