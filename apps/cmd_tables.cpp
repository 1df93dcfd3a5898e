// insmc tables: the report's Tables 3.1, 4.1, 4.2, 4.3, 5.1, 5.2 and the data
// of Figure 3.2, every cell computed from the model beside the printed value.
#include "apps/cli_common.h"
#include "apps/report_output.h"
#include "tables/tables_report.h"

namespace insmc::app {

int cmd_tables(const Args& args) {
  po::options_description opts("Options");
  opts.add_options()("format", po::value<std::string>()->default_value("markdown"),
                     "stdout: markdown (one table per printed table) or csv (one long table)")(
      "convention", po::value<std::string>()->default_value("paper"),
      "paper (the report's formulas as printed) or corrected (errors of the original fixed)")(
      "out", po::value<std::string>(), out_folder_help(tables::tables_report_outline()).c_str());
  opts.add(model_options_description());
  const auto vm = parse_args(args, "tables", "[--format markdown|csv] [--convention paper|corrected] [--out DIR]", opts);
  if (!vm) return 0;
  const mc::ReportOutline outline = tables::tables_report_outline();
  const mc::ReportFormat format = read_report_format(*vm, outline);
  const tables::TableConvention conv =
      tables::parse_table_convention((*vm)["convention"].as<std::string>(), "--convention");
  const ModelOptions model = read_model_options(*vm, true);
  std::optional<OutputFolderOption> out = prepare_report_folder(*vm, outline);
  write_report(tables::tables_report(tables::compute_tables(model, conv), conv), {format}, out, *vm);
  return 0;
}

}  // namespace insmc::app
