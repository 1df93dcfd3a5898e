// insmc effects: the truth simulator's named effects, their parameters with
// units and defaults, and a one-line description each.
#include "apps/cli_common.h"
#include "apps/report_output.h"
#include "montecarlo/study/write/catalogue_reports.h"

namespace insmc::app {

int cmd_effects(const Args& args) {
  po::options_description opts("Options");
  opts.add_options()("format", po::value<std::string>()->default_value("markdown"), "markdown or csv");
  const auto vm = parse_args(args, "effects", "[--format markdown|csv]", opts);
  if (!vm) return 0;
  const mc::ReportFormat format = read_report_format(*vm, mc::effects_report_outline());
  std::optional<OutputFolderOption> no_set;
  write_report(mc::effects_report(), {format}, no_set, *vm);
  return 0;
}

}  // namespace insmc::app
