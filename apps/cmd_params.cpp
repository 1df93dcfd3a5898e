// insmc params: the uncertainty catalogue (Table 3.1 and chapter 2) with the
// effective bound and distribution of each parameter.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include "apps/cli_common.h"
#include "apps/study_options.h"
#include "lib/uncertainty/catalogue.h"
#include "montecarlo/report/csv.h"
#include "montecarlo/report/json.h"
#include "montecarlo/report/markdown.h"

namespace insmc::app {

int run_params(const Args& args) {
  po::options_description opts("Options");
  opts.add_options()("format", po::value<std::string>()->default_value("markdown"), "markdown, csv or json");
  opts.add(uncertainty_options_description());
  const auto vm = parse_args(args, "params", "[--format markdown|csv|json] [--bound ...] [--dist ...]", opts);
  if (!vm) return 0;
  const OutputFormat format = parse_output_format((*vm)["format"].as<std::string>());
  const UncertaintyModel model = read_uncertainty_model(*vm);

  mc::Table table({"name", "group", "symbol", "si_unit", "bound_si", "bound_paper", "distribution", "fixed_si",
                   "systems", "per_alignment", "source"});
  mc::Json json = mc::Json::array();
  for (const auto& spec : catalogue()) {
    const ParameterDistribution& p = model.at(spec.index);
    const std::string si_unit(si_suffix(spec.dimension));
    const std::string bound_paper =
        fmt::format("{} {}", mc::format_number(p.bound_si / paper_unit_to_si(spec)), spec.paper_unit);
    const std::string systems = spec.applies == Applies::kBoth ? "1,2" : "1";
    const std::string fixed = p.kind == DistributionKind::kFixed ? mc::format_number(p.fixed_si) : "";
    table.add_row({std::string(spec.name), std::string(spec.group), std::string(spec.symbol), si_unit.empty() ? "1" : si_unit,
                   mc::format_number(p.bound_si), bound_paper, p.describe(), fixed, systems,
                   spec.per_alignment ? "yes" : "no", std::string(spec.source)});
    mc::Json row = mc::Json::object();
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
  switch (format) {
    case OutputFormat::kCsv: fmt::print("{}", mc::render_csv(table)); break;
    case OutputFormat::kJson: fmt::print("{}", json.dump()); break;
    case OutputFormat::kMarkdown:
      fmt::print("# Uncertainty catalogue (Table 3.1; SI inside)\n\n{}\nGroups (a name for --bound and --dist that "
                 "selects every parameter of the group; `all` selects every one): {}\n",
                 mc::render_markdown(table), fmt::join(uncertainty_groups(), ", "));
      break;
  }
  return 0;
}

}  // namespace insmc::app
