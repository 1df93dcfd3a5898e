#include "montecarlo/records/gap/ranking/effect_terms.h"

#include <fmt/format.h>

#include "lib/common/input_error.h"
#include "lib/records/record.h"
#include "lib/truth/effect.h"
#include "lib/units/quantity_display.h"

namespace insmc::gap {

EffectArgument effect_argument(const CandidateResult& c, const runs::RecordSite& site) {
  EffectArgument out;
  const std::optional<EffectKind> kind = find_effect(c.effect);
  if (!kind) return out;
  const EffectInfo* info = &kind->info();
  EffectSpec spec = default_effect(*kind);
  std::vector<bool> fitted(info->parameters.size(), false);
  for (std::size_t i = 0; i < info->parameters.size(); ++i)
    for (const ParameterEstimate& p : c.parameters)
      if (p.name == info->parameters[i].name) spec.values_si[i] = p.value, fitted[i] = true;
  bool any = false;
  for (const bool f : fitted) any = any || f;
  if (!any) return out;  // the candidate's parameters are not the effect's (e.g. a fitted offset for a J2 term)
  out.text = std::string(info->name);
  for (std::size_t i = 0; i < info->parameters.size(); ++i) {
    const EffectParameter& par = info->parameters[i];
    if (par.header_key == kKeyWarmupS) {  // the records state it: not fitted
      spec.values_si[i] = site.warmup_s;
      out.kept.push_back(fmt::format("warmup = {} ({})", format_quantity_rounded(site.warmup_s, par.dimension),
                                     site.warmup_from_header ? "the records' warmup_s"
                                                             : "the effect's default: no warmup_s in the header"));
    } else if (!fitted[i]) {
      out.kept.push_back(fmt::format("{} = {} (the effect's default)", par.name,
                                     format_quantity_rounded(spec.values_si[i], par.dimension)));
    }
    out.text += fmt::format("{}{}={}", i == 0 ? ":" : ",", par.name, format_quantity_rounded(spec.values_si[i], par.dimension));
  }
  // A grid point outside the effect's own range (a correlation time of 0,
  // the candidate's white-noise end) has no --effect form.
  try {
    validate_effect(parse_effect(out.text, "as_effect"), "as_effect");
  } catch (const InputError& e) {
    out.kept = {fmt::format("no --effect form: the fit lies outside the effect's range ({})", e.what())};
    out.text.clear();
  }
  return out;
}

}  // namespace insmc::gap
