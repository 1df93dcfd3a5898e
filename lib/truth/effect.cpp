#include "lib/truth/effect.h"

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "lib/common/assert.h"
#include "lib/common/closest_name.h"
#include "lib/common/input_text.h"
#include "lib/common/input_error.h"
#include "lib/truth/effects/effects.h"
#include "lib/units/units.h"

namespace insmc {
namespace {

/// The registry: the built-in effects (effects/effect_list.h), then those
/// added by register_effect(). Its order is the index of each EffectKind.
struct Registry {
  std::vector<const EffectDefinition*> definitions;
  std::vector<EffectInfo> infos;
};

Registry& registry() {
  static Registry r = [] {
    Registry out;
#define INSMC_EFFECT(name) out.definitions.push_back(&effects::name());
#include "lib/truth/effects/effect_list.h"
#undef INSMC_EFFECT
    for (const EffectDefinition* d : out.definitions) {
      INSMC_ASSERT(d->info.parameters.size() <= kMaxEffectParameters, "{} has {} parameters", d->info.name,
                   d->info.parameters.size());
      out.infos.push_back(d->info);
    }
    return out;
  }();
  return r;
}

std::string effect_names() {
  std::string out;
  for (const EffectInfo& e : effect_registry()) out += (out.empty() ? "" : ", ") + std::string(e.name);
  return out;
}

std::string parameter_names(const EffectInfo& e) {
  std::string out;
  for (const auto& p : e.parameters) out += (out.empty() ? "" : ", ") + std::string(p.name);
  return out.empty() ? "none" : out;
}


}  // namespace

std::span<const EffectInfo> effect_registry() { return registry().infos; }

EffectKind register_effect(const EffectDefinition& definition) {
  Registry& r = registry();
  for (const EffectInfo& e : r.infos)
    if (e.name == definition.info.name)
      throw std::logic_error(fmt::format("effect {} is registered already", e.name));
  INSMC_ASSERT(definition.info.parameters.size() <= kMaxEffectParameters, "{} has {} parameters",
               definition.info.name, definition.info.parameters.size());
  if (r.definitions.size() >= static_cast<std::size_t>(kMaxEffects))
    throw std::logic_error(fmt::format("effect {}: the registry holds {} effects at most", definition.info.name, kMaxEffects));
  r.definitions.push_back(&definition);
  r.infos.push_back(definition.info);
  return EffectKind(static_cast<int>(r.infos.size()) - 1);
}

const EffectInfo& EffectKind::info() const {
  const auto& infos = registry().infos;
  INSMC_ASSERT(index_ >= 0 && static_cast<std::size_t>(index_) < infos.size(), "no effect {}", index_);
  return infos[static_cast<std::size_t>(index_)];
}

const EffectInfo& effect_info(EffectKind kind) { return kind.info(); }

std::string_view to_string(EffectKind kind) { return kind.info().name; }

std::optional<EffectKind> find_effect(std::string_view name) {
  const auto infos = effect_registry();
  for (std::size_t k = 0; k < infos.size(); ++k)
    if (infos[k].name == name) return EffectKind(static_cast<int>(k));
  return std::nullopt;
}

EffectKind parse_effect_kind(std::string_view text, std::string_view field) {
  if (const auto kind = find_effect(text)) return *kind;
  std::vector<std::string> names;
  for (const EffectInfo& e : effect_registry()) names.emplace_back(e.name);
  throw InputError(std::string(field), echo_input(text),
                   "unknown effect" + did_you_mean(text, names) + "; expected one of " + effect_names());
}

double EffectSpec::value(std::string_view name) const {
  const EffectInfo& info = effect_info(kind);
  for (std::size_t i = 0; i < info.parameters.size(); ++i)
    if (info.parameters[i].name == name) return values_si[i];
  INSMC_ASSERT(false, "effect {} has no parameter {}", info.name, name);
  return 0.0;
}

namespace {

/// The parameter's allowed values: its sign (range) and |value| <= its limit.
PhysicalRange physical_range(const EffectParameter& p) {
  const double limit = p.limit_si > 0 ? p.limit_si : magnitude_limit(p.dimension);
  switch (p.range) {
    case ParameterRange::kAny: return {-limit, limit};
    case ParameterRange::kNonNegative: return {0.0, limit};
    case ParameterRange::kPositive: return {0.0, limit, true};
  }
  return {0.0, limit};
}

}  // namespace

EffectSpec default_effect(EffectKind kind) {
  EffectSpec spec;
  spec.kind = kind;
  const EffectInfo& info = effect_info(kind);
  for (std::size_t i = 0; i < info.parameters.size(); ++i) spec.values_si[i] = info.parameters[i].default_si;
  return spec;
}

void validate_effect(const EffectSpec& spec, std::string_view field) {
  const EffectInfo& info = effect_info(spec.kind);
  for (std::size_t i = 0; i < info.parameters.size(); ++i) {
    const EffectParameter& p = info.parameters[i];
    const double v = spec.values_si[i];
    const std::string name = fmt::format("{} {}.{}", field, info.name, p.name);
    require_in_range(name, v, p.dimension, physical_range(p));
  }
  if (info.check) info.check(spec, field);
}

namespace {
/// A parameter "after 1 h" of a random walk (angle_1h, velocity_1h) also
/// takes the walk's data-sheet value: 0.005degprth is 0.005 deg after 1 h.
double parse_effect_value(std::string_view value, const EffectParameter& p, const std::string& field) {
  // A random walk's value after 1 h takes the walk's units in every spelling
  // (0.03mpsprth, 0.03m/s/√h): the unit, read whole, decides.
  if (p.name.ends_with("_1h") && (p.dimension == Dimension::kAngle || p.dimension == Dimension::kVelocity)) {
    const Dimension walk = p.dimension == Dimension::kAngle ? Dimension::kAngleRandomWalk : Dimension::kVelocityRandomWalk;
    const std::optional<QuantityText> q = split_quantity(value);
    if (q && unit_factor(q->unit, walk)) return parse_quantity(value, walk, field) * std::sqrt(kHourToS);
  }
  return parse_quantity(value, p.dimension, field);
}
}  // namespace

EffectSpec parse_effect(std::string_view text, std::string_view field) {
  text = trim(text);
  const std::size_t colon = text.find(':');
  const std::string_view name = trim(text.substr(0, colon));
  const EffectKind kind = parse_effect_kind(name, field);
  EffectSpec spec = default_effect(kind);
  const EffectInfo& info = effect_info(kind);
  if (colon != std::string_view::npos) {
    std::string_view rest = text.substr(colon + 1);
    std::array<bool, kMaxEffectParameters> seen{};
    while (true) {
      const std::size_t comma = rest.find(',');
      const std::string_view item = trim(rest.substr(0, comma));
      const std::size_t eq = item.find('=');
      if (item.empty() || eq == std::string_view::npos)
        throw InputError(fmt::format("{} {}", field, info.name), std::string(item),
                         "expected param=value; parameters: " + parameter_names(info));
      const std::string_view key = trim(item.substr(0, eq));
      const std::string_view value = trim(item.substr(eq + 1));
      std::size_t index = info.parameters.size();
      for (std::size_t i = 0; i < info.parameters.size(); ++i)
        if (info.parameters[i].name == key) index = i;
      const std::string param_field = fmt::format("{} {}.{}", field, info.name, key);
      if (index == info.parameters.size())
        throw InputError(param_field, std::string(value),
                         "unknown parameter; expected one of " + parameter_names(info));
      if (seen[index]) throw InputError(param_field, std::string(value), "given twice");
      seen[index] = true;
      spec.values_si[index] = parse_effect_value(value, info.parameters[index], param_field);
      if (comma == std::string_view::npos) break;
      rest = rest.substr(comma + 1);
    }
  }
  validate_effect(spec, field);
  return spec;
}

std::string format_effect(const EffectSpec& spec) {
  const EffectInfo& info = effect_info(spec.kind);
  std::string out(info.name);
  for (std::size_t i = 0; i < info.parameters.size(); ++i) {
    out += (i == 0 ? ":" : ",");
    out += fmt::format("{}={}", info.parameters[i].name,
                       format_quantity(spec.values_si[i], info.parameters[i].dimension));
  }
  return out;
}

std::uint64_t effect_stream(EffectKind kind, int occurrence) {
  return (static_cast<std::uint64_t>(kind.index()) + 1) << 16 | static_cast<std::uint64_t>(occurrence);
}

Perturbations realize_effects(std::span<const EffectSpec> effects, const EffectContext& context) {
  Perturbations p;
  const Registry& r = registry();
  std::array<int, kMaxEffects> occurrences{};
  static const NormalSource kNoNoise;
  for (const EffectSpec& spec : effects) {
    const auto k = static_cast<std::size_t>(spec.kind.index());
    const EffectDefinition& def = *r.definitions.at(k);
    INSMC_ASSERT(!def.info.random || context.noise != nullptr,
                 "effect {} is random but no NormalSource was given", def.info.name);
    NormalDraws draws(context.noise ? *context.noise : kNoNoise, effect_stream(spec.kind, occurrences[k]++));
    def.realize(spec, context, draws, p);
  }
  return p;
}

}  // namespace insmc
