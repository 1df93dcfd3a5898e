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
#include <compare>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "lib/truth/noise.h"
#include "lib/truth/perturbations.h"
#include "lib/units/physical_range.h"
#include "lib/units/quantity.h"

namespace insmc {

struct EffectInfo;
struct EffectSpec;

/// A named effect: its place in the registry (effect_registry()), whose
/// order is the index. The built-in effects are listed once, in
/// effects/effect_list.h; register_effect() adds one defined elsewhere.
class EffectKind {
 public:
  constexpr EffectKind() = default;
  constexpr explicit EffectKind(int index) : index_(index) {}
  constexpr int index() const { return index_; }
  constexpr auto operator<=>(const EffectKind&) const = default;
  const EffectInfo& info() const;

 private:
  int index_ = 0;
};

inline constexpr int kMaxEffectParameters = 6;
/// Effects in the registry at most (the built-in ones and those registered).
inline constexpr int kMaxEffects = 64;

/// Allowed sign of a parameter value.
enum class ParameterRange { kAny, kNonNegative, kPositive };

/// How an effect's magnitude m scales a parameter (gap-validate's files of
/// an effect at m times its default).
enum class EffectMagnitude {
  kFixed,   ///< kept at its default
  kScaled,  ///< m × default
  /// The model's own value plus m × the default's excess over it (a pulse
  /// weight: m = 0 is the model's own counter, 1 the default).
  kExcessOverModelPulse,
};

/// The sensor whose raw outputs show an effect (what a raw-sensor stage of
/// `import-imu` records measures of it).
enum class RawSensor { kNone, kGyro, kAccelerometer };

/// Which fitted raw noise term bounds a parameter (the raw-sensor stage of
/// import-imu records, docs/noise.md).
enum class RawSensorLimit {
  kNone,
  kWhiteNoise1h,  ///< the white noise after 1 h (N·√3600 s) of the effect's sensor
  kBiasWander,    ///< the bias wander of the effect's sensor
  kVelocityQuantization,  ///< the accelerometers' velocity quantization
};

struct EffectParameter {
  std::string_view name;         ///< e.g. "sigma"
  Dimension dimension;           ///< unit family (SI inside)
  double default_si;             ///< default value [SI]
  std::string_view description;  ///< one line
  ParameterRange range = ParameterRange::kNonNegative;
  /// Physical ceiling of |value|; 0 = magnitude_limit(dimension)
  /// (lib/units/physical_range.h). validate_effect() refuses values beyond.
  double limit_si = 0.0;
  /// How the effect's magnitude (`gap-validate --magnitudes`) acts on it.
  EffectMagnitude magnitude = EffectMagnitude::kFixed;
  /// What a raw-sensor stage's fit bounds it by (the diagnosis limits the
  /// effect's candidate to it, docs/gap-method.md §4).
  RawSensorLimit raw_limit = RawSensorLimit::kNone;
  /// The record header key that states it for a set of records (e.g.
  /// "warmup_s"): a finding takes it from there rather than fitting it.
  std::string_view header_key = {};
};

/// What the registry says about one effect.
struct EffectInfo {
  std::string_view name;         ///< e.g. "accel_bias_instability"
  std::string_view description;  ///< one line of physics
  std::span<const EffectParameter> parameters;
  bool random;                   ///< draws from the NormalSource
  RawSensor sensor = RawSensor::kNone;
  /// It acts on the ΔV pulse counting: records of it must keep the counts.
  bool needs_pulses = false;
  /// Checks across its parameters beyond each one's range (e.g. sway's
  /// periods in order); throws InputError naming `field`. May be empty.
  void (*check)(const EffectSpec& spec, std::string_view field) = nullptr;
};

/// An effect with its parameter values (SI, in the registry's order).
struct EffectSpec {
  EffectKind kind;  ///< the registry's first effect unless set
  std::array<double, kMaxEffectParameters> values_si{};

  /// The value of the parameter named `name` (asserts that it exists).
  double value(std::string_view name) const;
};

/// Every effect, in registry order (EffectKind's index).
std::span<const EffectInfo> effect_registry();
const EffectInfo& effect_info(EffectKind kind);
std::string_view to_string(EffectKind kind);
/// The effect named `name`, if the registry has one.
std::optional<EffectKind> find_effect(std::string_view name);
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

/// Adds an effect's contribution to `p`. `draws` is the effect's own stream
/// (used only by random effects).
using RealizeEffectFn = void (*)(const EffectSpec& spec, const EffectContext& context, NormalDraws& draws,
                                 Perturbations& p);

/// One effect: what the registry says about it and how it is realized.
struct EffectDefinition {
  EffectInfo info;
  RealizeEffectFn realize;
};

/// Adds an effect to the registry (one defined outside this library, e.g.
/// in a test) and returns its handle. Call before any effect is parsed or
/// realized; throws std::logic_error on a name in use. `definition` must
/// outlive every use of the handle.
EffectKind register_effect(const EffectDefinition& definition);

/// Realizes every effect of a run (draws made here, once), summing their
/// contributions.
Perturbations realize_effects(std::span<const EffectSpec> effects, const EffectContext& context);

}  // namespace insmc
