// insmc effects: the truth simulator's named effects, their parameters with
// units and defaults, and a one-line description each.
#include <fmt/format.h>

#include "apps/cli_common.h"
#include "lib/common/input_error.h"
#include "lib/truth/effect.h"
#include "lib/units/quantity.h"
#include "montecarlo/report/csv.h"
#include "montecarlo/report/markdown.h"

namespace insmc::app {

int run_effects(const Args& args) {
  po::options_description opts("Options");
  opts.add_options()("format", po::value<std::string>()->default_value("markdown"), "markdown or csv");
  const auto vm = parse_args(args, "effects", "[--format markdown|csv]", opts);
  if (!vm) return 0;
  const OutputFormat format = parse_output_format((*vm)["format"].as<std::string>());
  if (format == OutputFormat::kJson) throw InputError("--format", "json", "effects offers markdown or csv");
  mc::Table t({"effect", "parameter", "default", "si_unit", "description"});
  for (const EffectInfo& e : effect_registry()) {
    t.add_row({std::string(e.name), "", "", "", std::string(e.description)});
    for (const EffectParameter& p : e.parameters)
      t.add_row({std::string(e.name), std::string(p.name), format_quantity(p.default_si, p.dimension),
                 std::string(si_suffix(p.dimension)), std::string(p.description)});
  }
  if (format == OutputFormat::kCsv) {
    fmt::print("{}", mc::render_csv(t));
  } else {
    fmt::print("# Truth-simulator effects\n\nUse as --effect NAME or --effect NAME:param=value,... "
               "(values with units). An effect named without parameters takes these defaults.\n\n{}",
               mc::render_markdown(t));
  }
  return 0;
}

}  // namespace insmc::app
