#pragma once
/// The truth simulator's named effects (docs/truth-vs-models.md): physical
/// behaviour the report's model does not have, each with a name, parameters
/// with units and defaults, and a one-line description. `insmc effects` lists
/// the registry; `--effect NAME[:param=value,...]` selects one (values with
/// units, parsed by parse_quantity). Effects are independent and combinable:
/// each is realized into additive terms of a Perturbations (perturbations.h).
/// An effect named without parameters takes defaults chosen so that it is
/// clearly visible in 20 runs of 105 min.
#include <array>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "lib/truth/noise.h"
#include "lib/truth/perturbations.h"
#include "lib/units/physical_range.h"
#include "lib/units/quantity.h"

namespace insmc {

/// One value per effect; the registry (effect_registry()) is in this order.
enum class EffectKind : int {
  kQuantization,
  kSway,
  kAccelBiasInstability,
  kGyroDriftInstability,
  kAngleRandomWalk,
  kVelocityRandomWalk,
  kThermalTransient,
  kAnisoelasticDrift,
  kScaleFactorNonlinearity,
  kGravityModel,
  kDeflectionOfVertical,
  kAlignmentTransient,
  kSwitchTransient,
};
inline constexpr int kEffectKindCount = 13;
inline constexpr int kMaxEffectParameters = 6;

/// Allowed sign of a parameter value.
enum class ParameterRange { kAny, kNonNegative, kPositive };

struct EffectParameter {
  std::string_view name;         ///< e.g. "sigma"
  Dimension dimension;           ///< unit family (SI inside)
  double default_si;             ///< default value [SI]
  std::string_view description;  ///< one line
  ParameterRange range = ParameterRange::kNonNegative;
  /// Physical ceiling of |value|; 0 = magnitude_limit(dimension)
  /// (lib/units/physical_range.h). validate_effect() refuses values beyond.
  double limit_si = 0.0;
};

/// The parameter's allowed values: its sign (range) and |value| <= its limit.
PhysicalRange physical_range(const EffectParameter& parameter);

/// What the registry says about one effect.
struct EffectInfo {
  EffectKind kind;
  std::string_view name;         ///< e.g. "accel_bias_instability"
  std::string_view description;  ///< one line of physics
  std::span<const EffectParameter> parameters;
  bool random;                   ///< draws from the NormalSource
};

/// An effect with its parameter values (SI, in the registry's order).
struct EffectSpec {
  EffectKind kind = EffectKind::kQuantization;
  std::array<double, kMaxEffectParameters> values_si{};

  /// The value of the parameter named `name` (asserts that it exists).
  double value(std::string_view name) const;
};

/// Every effect, in EffectKind order.
std::span<const EffectInfo> effect_registry();
const EffectInfo& effect_info(EffectKind kind);
std::string_view to_string(EffectKind kind);
/// Parses an effect name; throws InputError naming `field` with the list of
/// names otherwise.
EffectKind parse_effect_kind(std::string_view text, std::string_view field = "effect");

/// The effect with every parameter at its default.
EffectSpec default_effect(EffectKind kind);

/// Parses "NAME" or "NAME:param=value,param=value" (values with units).
/// Throws InputError naming the field (e.g. "effect sway.accel_rms") on an
/// unknown effect or parameter, a repeated parameter, a bad value or unit, or
/// a value out of range (and the cross-parameter checks, e.g. sway periods).
EffectSpec parse_effect(std::string_view text, std::string_view field = "effect");

/// "NAME:p=v,..." with every parameter, in units format_quantity picks; parses
/// back to the same spec (up to 12 significant digits).
std::string format_effect(const EffectSpec& spec);

/// Checks ranges of an already built spec; throws InputError naming `field`.
void validate_effect(const EffectSpec& spec, std::string_view field = "effect");

/// What an effect may know when it is realized for a run.
struct EffectContext {
  double duration_s = 0.0;          ///< the run's last time (grid length) [s]
  double noise_grid_s = 1.0;        ///< grid of random processes [s], > 0
  double site_gravity_mps2 = 0.0;   ///< |f| at the site [m/s²]
  double latitude_rad = 0.0;        ///< L0
  double earth_rate_radps = 0.0;    ///< ω_ie
  const NormalSource* noise = nullptr;  ///< required when an effect is random
};

/// Stream of the `occurrence`-th effect of `kind` in a run (occurrence counts
/// repeated kinds): distinct per (kind, occurrence), stable when other effects
/// are added or removed.
std::uint64_t effect_stream(EffectKind kind, int occurrence);

/// Realizes every effect of a run (draws made here, once), summing their
/// contributions.
Perturbations realize_effects(std::span<const EffectSpec> effects, const EffectContext& context);

}  // namespace insmc
