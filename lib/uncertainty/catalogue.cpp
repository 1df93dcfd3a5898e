#include "lib/uncertainty/catalogue.h"

#include <algorithm>
#include <vector>

#include "lib/units/units.h"

namespace insmc {
namespace {

using D = Dimension;
constexpr Applies kBoth = Applies::kBoth;

// Table 3.1, with these defaults where the paper leaves a choice (it bounds ζ
// and ∂f only as a whole):
// ζ = ζ_c + ζ_r and ∂f = ∂f_c + ∂f_r are each split half and half, each part
// bounded by half the Table 3.1 bound (kDefaultRandomFraction; the split is a
// study parameter, lib/uncertainty/random_fraction.h).
constexpr double kMg = kMgToMps2;
constexpr double kMeru = kMeruToRadps;
constexpr double kMrad = kMradToRad;

constexpr std::array<UncertaintySpec, uncertainty_slot::kDim> kCatalogue = {{
    {"accel_bias_x", "accel_bias", "δf_x", uncertainty_slot::kAccelBias + 0, D::kAcceleration, 1 * kMg, "mg", kBoth, false, "Table 3.1 (<1 mg)"},
    {"accel_bias_y", "accel_bias", "δf_y", uncertainty_slot::kAccelBias + 1, D::kAcceleration, 1 * kMg, "mg", kBoth, false, "Table 3.1 (<1 mg)"},
    {"accel_bias_z", "accel_bias", "δf_z", uncertainty_slot::kAccelBias + 2, D::kAcceleration, 1 * kMg, "mg", kBoth, false, "Table 3.1 (<1 mg)"},
    {"accel_scale_x", "accel_scale", "a_x", uncertainty_slot::kAccelScale + 0, D::kDimensionless, 1e-4, "ppm", kBoth, false, "Table 3.1 (<1e-4)"},
    {"accel_scale_y", "accel_scale", "a_y", uncertainty_slot::kAccelScale + 1, D::kDimensionless, 1e-4, "ppm", kBoth, false, "Table 3.1 (<1e-4)"},
    {"accel_scale_z", "accel_scale", "a_z", uncertainty_slot::kAccelScale + 2, D::kDimensionless, 1e-4, "ppm", kBoth, false, "Table 3.1 (<1e-4)"},
    {"bias_change_const_x", "bias_change_const", "∂f_cx", uncertainty_slot::kBiasChangeConst + 0, D::kAcceleration, 0.05 * kMg, "mg", kBoth, false, "Table 3.1 ∂f (<0.1 mg), constant part (1 - --random-fraction)"},
    {"bias_change_const_y", "bias_change_const", "∂f_cy", uncertainty_slot::kBiasChangeConst + 1, D::kAcceleration, 0.05 * kMg, "mg", kBoth, false, "Table 3.1 ∂f (<0.1 mg), constant part (1 - --random-fraction)"},
    {"bias_change_align_x", "bias_change_align", "∂f_rx", uncertainty_slot::kBiasChangeAlign + 0, D::kAcceleration, 0.05 * kMg, "mg", kBoth, true, "Table 3.1 ∂f (<0.1 mg), part per alignment (--random-fraction)"},
    {"bias_change_align_y", "bias_change_align", "∂f_ry", uncertainty_slot::kBiasChangeAlign + 1, D::kAcceleration, 0.05 * kMg, "mg", kBoth, true, "Table 3.1 ∂f (<0.1 mg), part per alignment (--random-fraction)"},
    {"gyro_drift_x", "gyro_drift", "ω_dox", uncertainty_slot::kGyroDrift + 0, D::kAngularRate, 10 * kMeru, "meru", kBoth, false, "Table 3.1 (<10 meru)"},
    {"gyro_drift_y", "gyro_drift", "ω_doy", uncertainty_slot::kGyroDrift + 1, D::kAngularRate, 10 * kMeru, "meru", kBoth, false, "Table 3.1 (<10 meru)"},
    {"gyro_drift_z", "gyro_drift", "ω_doz", uncertainty_slot::kGyroDrift + 2, D::kAngularRate, 10 * kMeru, "meru", kBoth, false, "Table 3.1 (<10 meru)"},
    {"gyro_mu_drift_x", "gyro_mu_drift", "ω_MUx", uncertainty_slot::kGyroMuDrift + 0, D::kAngularRate, 5 * kMeru, "meru", kBoth, false, "Table 3.1 (<5 meru), (3.13a)"},
    {"gyro_mu_drift_y", "gyro_mu_drift", "ω_MUy", uncertainty_slot::kGyroMuDrift + 1, D::kAngularRate, 5 * kMeru, "meru", kBoth, false, "Table 3.1 (<5 meru), (3.13a)"},
    {"gyro_mu_drift_z", "gyro_mu_drift", "ω_MUz", uncertainty_slot::kGyroMuDrift + 2, D::kAngularRate, 5 * kMeru, "meru", kBoth, false, "Table 3.1 (<5 meru), (3.13a)"},
    {"gyro_muy_drift_x", "gyro_muy_drift", "g·MUY_x", uncertainty_slot::kGyroMuyDrift + 0, D::kAngularRate, 10 * kMeru, "meru", kBoth, false, "Table 3.1 (<10 meru)"},
    {"gyro_muy_drift_y", "gyro_muy_drift", "g·MUY_y", uncertainty_slot::kGyroMuyDrift + 1, D::kAngularRate, 10 * kMeru, "meru", kBoth, false, "Table 3.1 (<10 meru)"},
    {"gyro_muy_drift_z", "gyro_muy_drift", "g·MUY_z", uncertainty_slot::kGyroMuyDrift + 2, D::kAngularRate, 10 * kMeru, "meru", kBoth, false, "Table 3.1 (<10 meru)"},
    {"misalign_const_x", "misalign_const", "ζ_cx", uncertainty_slot::kMisalignConst + 0, D::kAngle, 0.5 * kMrad, "mrad", kBoth, false, "Table 3.1 ζ (<1 mrad), constant part (1 - --random-fraction)"},
    {"misalign_const_y", "misalign_const", "ζ_cy", uncertainty_slot::kMisalignConst + 1, D::kAngle, 0.5 * kMrad, "mrad", kBoth, false, "Table 3.1 ζ (<1 mrad), constant part (1 - --random-fraction)"},
    {"misalign_const_z", "misalign_const", "ζ_cz", uncertainty_slot::kMisalignConst + 2, D::kAngle, 0.5 * kMrad, "mrad", kBoth, false, "Table 3.1 ζ (<1 mrad), constant part (1 - --random-fraction)"},
    {"misalign_align_x", "misalign_align", "ζ_rx", uncertainty_slot::kMisalignAlign + 0, D::kAngle, 0.5 * kMrad, "mrad", kBoth, true, "Table 3.1 ζ (<1 mrad), part per alignment (--random-fraction)"},
    {"misalign_align_y", "misalign_align", "ζ_ry", uncertainty_slot::kMisalignAlign + 1, D::kAngle, 0.5 * kMrad, "mrad", kBoth, true, "Table 3.1 ζ (<1 mrad), part per alignment (--random-fraction)"},
    {"misalign_align_z", "misalign_align", "ζ_rz", uncertainty_slot::kMisalignAlign + 2, D::kAngle, 0.5 * kMrad, "mrad", kBoth, true, "Table 3.1 ζ (<1 mrad), part per alignment (--random-fraction)"},
    {"theodolite_azimuth", "theodolite_azimuth", "(u)ψ", uncertainty_slot::kTheodolite, D::kAngle, 1 * kMrad, "mrad", Applies::kSystem1Only, false, "Table 3.1 (<1 mrad), system 1"},
    {"deflection_xi", "deflection", "ξ", uncertainty_slot::kDeflection + 0, D::kAngle, 0.1 * kMrad, "mrad", kBoth, false, "Table 3.1 (<0.1 mrad)"},
    {"deflection_eta", "deflection", "η", uncertainty_slot::kDeflection + 1, D::kAngle, 0.1 * kMrad, "mrad", kBoth, false, "Table 3.1 (<0.1 mrad)"},
    {"initial_velocity_x", "initial_velocity", "(u)V_x", uncertainty_slot::kInitialVelocity + 0, D::kVelocity, 0.3, "mps", kBoth, true, "Table 3.1 δV(0) (<0.3 m/s)"},
    {"initial_velocity_y", "initial_velocity", "(u)V_y", uncertainty_slot::kInitialVelocity + 1, D::kVelocity, 0.3, "mps", kBoth, true, "Table 3.1 δV(0) (<0.3 m/s)"},
    {"initial_velocity_z", "initial_velocity", "(u)V_z", uncertainty_slot::kInitialVelocity + 2, D::kVelocity, 0.3, "mps", kBoth, true, "Table 3.1 δV(0) (<0.3 m/s)"},
    {"latitude_error", "latitude_error", "δL_0", uncertainty_slot::kLatitudeError, D::kAngle, 0.1 * kMrad, "mrad", kBoth, false, "Table 3.1 (<0.1 mrad)"},
    {"altitude_error", "altitude_error", "δh", uncertainty_slot::kAltitudeError, D::kLength, 100.0, "m", kBoth, false, "Table 3.1 (<100 m)"},
    // The schemes' measurement errors (the report states no bounds; these
    // are the project's choices, each acting only in its scheme):
    // 5.4's drift estimate −ω_c − ω_ie E4 (5.15): E4 within 1e-4 (0.1 meru), the
    // unit Table 5.2 quotes ε4 in, a torquer scale factor of 1e-4 (Table 3.1's
    // bound on the accelerometers') acting on the earth-rate commands of (5.14).
    {"alignment_drift_error_x", "alignment_drift_error", "ω_ie ε4x", uncertainty_slot::kAlignDriftError + 0, D::kAngularRate, 0.1 * kMeru, "meru", kBoth, false, "project's choice: 1e-4 ω_ie, (5.15a)"},
    {"alignment_drift_error_y", "alignment_drift_error", "ω_ie ε4y", uncertainty_slot::kAlignDriftError + 1, D::kAngularRate, 0.1 * kMeru, "meru", kBoth, false, "project's choice: 1e-4 ω_ie, (5.15a)"},
    {"alignment_drift_error_z", "alignment_drift_error", "ω_ie ε4z", uncertainty_slot::kAlignDriftError + 2, D::kAngularRate, 0.1 * kMeru, "meru", kBoth, false, "project's choice: 1e-4 ω_ie, (5.15a)"},
    // 5.2/5.3's resets at T (points 5, 6 of (5.8)): the registers set to the
    // resolution of what they hold, the position computer's (§4.3, "a few
    // feet") and one ΔV pulse (§4.3, 0.1 ft/s).
    {"reset_position_error_x", "reset_position_error", "δr_reset,x", uncertainty_slot::kResetPositionError + 0, D::kLength, 3 * kFtToM, "m", kBoth, false, "project's choice: 3 ft, the position resolution, (5.8)"},
    {"reset_position_error_y", "reset_position_error", "δr_reset,y", uncertainty_slot::kResetPositionError + 1, D::kLength, 3 * kFtToM, "m", kBoth, false, "project's choice: 3 ft, the position resolution, (5.8)"},
    {"reset_position_error_z", "reset_position_error", "δr_reset,z", uncertainty_slot::kResetPositionError + 2, D::kLength, 3 * kFtToM, "m", kBoth, false, "project's choice: 3 ft, the position resolution, (5.8)"},
    {"reset_velocity_error_x", "reset_velocity_error", "δv_reset,x", uncertainty_slot::kResetVelocityError + 0, D::kVelocity, 0.1 * kFtpsToMps, "mps", kBoth, false, "project's choice: 0.1 ft/s, one ΔV pulse, (5.8)"},
    {"reset_velocity_error_y", "reset_velocity_error", "δv_reset,y", uncertainty_slot::kResetVelocityError + 1, D::kVelocity, 0.1 * kFtpsToMps, "mps", kBoth, false, "project's choice: 0.1 ft/s, one ΔV pulse, (5.8)"},
    {"reset_velocity_error_z", "reset_velocity_error", "δv_reset,z", uncertainty_slot::kResetVelocityError + 2, D::kVelocity, 0.1 * kFtpsToMps, "mps", kBoth, false, "project's choice: 0.1 ft/s, one ΔV pulse, (5.8)"},
    {"realignment_azimuth_error", "realignment_azimuth_error", "δψ_r", uncertainty_slot::kRealignAzimuthError, D::kAngle, 0.1 * kMrad, "mrad", Applies::kSystem1Only, false, "project's choice: 0.1 mrad, a tenth of (u)ψ, theodolite re-sighting at 5.1.x's realignment"},
}};

constexpr bool indices_match_positions() {
  for (int i = 0; i < uncertainty_slot::kDim; ++i)
    if (kCatalogue[i].index != i) return false;
  return true;
}
static_assert(indices_match_positions(), "catalogue order must equal UncertaintyVector order");

}  // namespace

std::span<const UncertaintySpec> catalogue() { return kCatalogue; }

std::optional<UncertaintySpec> find_uncertainty(std::string_view name) {
  for (const auto& spec : kCatalogue)
    if (spec.name == name) return spec;
  return std::nullopt;
}

bool is_scheme_error(const UncertaintySpec& spec) {
  return std::find(kSchemeErrorGroups.begin(), kSchemeErrorGroups.end(), spec.group) != kSchemeErrorGroups.end();
}

std::vector<int> select_uncertainties(std::string_view name_or_group) {
  std::vector<int> out;
  for (const auto& spec : kCatalogue) {
    if (name_or_group == "all" || spec.name == name_or_group || spec.group == name_or_group ||
        (name_or_group == kSchemeErrorsGroup && is_scheme_error(spec)))
      out.push_back(spec.index);
  }
  return out;
}

std::vector<std::string> uncertainty_groups() {
  std::vector<std::string> out;
  for (const auto& spec : kCatalogue)
    if (out.empty() || out.back() != spec.group) out.emplace_back(spec.group);
  out.emplace_back(kSchemeErrorsGroup);
  return out;
}

PhysicalRange bound_range(const UncertaintySpec& spec) {
  if (spec.index == uncertainty_slot::kAltitudeError) return {0.0, 1e4};
  return non_negative_range(spec.dimension);
}

UncertaintyVector default_bounds() {
  UncertaintyVector b;
  for (const auto& spec : kCatalogue) b[spec.index] = spec.default_bound_si;
  return b;
}

double paper_unit_to_si(const UncertaintySpec& spec) {
  const std::string_view u = spec.paper_unit;
  if (u == "mg") return kMgToMps2;
  if (u == "ppm") return kPpmToUnit;
  if (u == "meru") return kMeruToRadps;
  if (u == "mrad") return kMradToRad;
  return 1.0;  // m, mps: SI already
}

}  // namespace insmc
