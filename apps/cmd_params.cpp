// insmc params: the uncertainty catalogue (Table 3.1 and chapter 2) with the
// effective bound and distribution of each parameter.
#include "apps/cli_common.h"
#include "apps/report_output.h"
#include "apps/study_options.h"
#include "montecarlo/study/write/catalogue_reports.h"

namespace insmc::app {

int cmd_params(const Args& args) {
  po::options_description opts("Options");
  opts.add_options()("format", po::value<std::string>()->default_value("markdown"), "markdown, csv or json");
  opts.add(uncertainty_options_description());
  const auto vm = parse_args(args, "params", "[--format markdown|csv|json] [--bound ...] [--dist ...]", opts);
  if (!vm) return 0;
  const mc::ReportOutline outline = mc::params_report_outline();
  const mc::ReportFormat format = read_report_format(*vm, outline);
  std::optional<OutputFolderOption> no_set;
  write_report(mc::params_report(read_uncertainty_model(*vm)), {format}, no_set, *vm);
  return 0;
}

}  // namespace insmc::app
