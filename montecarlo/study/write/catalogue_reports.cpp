#include "montecarlo/study/write/catalogue_reports.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "lib/truth/effect.h"
#include "lib/uncertainty/catalogue.h"
#include "lib/units/quantity.h"
#include "montecarlo/report/csv.h"
#include "montecarlo/report/json.h"
#include "montecarlo/report/markdown.h"

namespace insmc::mc {

ReportOutline params_report_outline() { return {"params", {}, {}}; }

Report params_report(const UncertaintyModel& model) {
  Table table({"name", "group", "symbol", "si_unit", "bound_si", "bound_paper", "distribution", "fixed_si",
               "systems", "per_alignment", "source"});
  Json json = Json::array();
  for (const auto& spec : catalogue()) {
    const ParameterDistribution& p = model.at(spec.index);
    const std::string si_unit(si_suffix(spec.dimension));
    const std::string bound_paper =
        fmt::format("{} {}", format_number(p.bound_si / paper_unit_to_si(spec)), spec.paper_unit);
    const std::string systems = spec.applies == Applies::kBoth ? "1,2" : "1";
    const std::string fixed = p.kind == DistributionKind::kFixed ? format_number(p.fixed_si) : "";
    table.add_row({std::string(spec.name), std::string(spec.group), std::string(spec.symbol), si_unit.empty() ? "1" : si_unit,
                   format_number(p.bound_si), bound_paper, p.describe(), fixed, systems,
                   spec.per_alignment ? "yes" : "no", std::string(spec.source)});
    Json row = Json::object();
    row["name"] = std::string(spec.name);
    row["group"] = std::string(spec.group);
    row["symbol"] = std::string(spec.symbol);
    row["si_unit"] = si_unit;
    row["bound_si"] = p.bound_si;
    row["distribution"] = p.describe();
    if (p.kind == DistributionKind::kFixed) row["fixed_si"] = p.fixed_si;
    row["systems"] = systems;
    row["per_alignment"] = spec.per_alignment;
    row["source"] = std::string(spec.source);
    json.push_back(row);
  }
  Report report(params_report_outline());
  report.shown(ReportFormat::kCsv, render_csv(table))
      .shown(ReportFormat::kJson, json.dump())
      .shown(ReportFormat::kMarkdown,
             fmt::format("# Uncertainty catalogue (Table 3.1; SI inside)\n\n{}\nGroups (a name for --bound and --dist "
                         "that selects every parameter of the group; `all` selects every one): {}\n",
                         render_markdown(table), fmt::join(uncertainty_groups(), ", ")));
  return report;
}

ReportOutline effects_report_outline() {
  return {"effects", {}, {}, {ReportFormat::kMarkdown, ReportFormat::kCsv}};
}

Report effects_report() {
  Table t({"effect", "parameter", "default", "si_unit", "description"});
  for (const EffectInfo& e : effect_registry()) {
    t.add_row({std::string(e.name), "", "", "", std::string(e.description)});
    for (const EffectParameter& p : e.parameters)
      t.add_row({std::string(e.name), std::string(p.name), format_quantity(p.default_si, p.dimension),
                 std::string(si_suffix(p.dimension)), std::string(p.description)});
  }
  Report report(effects_report_outline());
  report.shown(ReportFormat::kCsv, render_csv(t))
      .shown(ReportFormat::kMarkdown,
             fmt::format("# Truth-simulator effects\n\nUse as --effect NAME or --effect NAME:param=value,... "
                         "(values with units). An effect named without parameters takes these defaults.\n\n{}",
                         render_markdown(t)));
  return report;
}

}  // namespace insmc::mc
