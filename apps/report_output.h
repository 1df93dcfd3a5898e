#pragma once
/// The one writer of every command's report (montecarlo/report/report.h):
/// `--format` checked against what the command offers before the work (and
/// `--out` by prepare_report_folder, apps/output_paths.h); after it, the set
/// written whole and stdout printed in the chosen format.
#include <optional>
#include <vector>

#include "apps/output_paths.h"
#include "apps/stdout_choice.h"
#include "montecarlo/report/report.h"

namespace insmc::app {

/// --format of a command whose report has `outline` ("markdown" or "md",
/// "csv", "json"); one it does not offer is refused now (InputError naming
/// what it offers).
mc::ReportFormat read_report_format(const po::variables_map& vm, const mc::ReportOutline& outline);

/// Writes `report`'s set into `out` when given, then prints what `shown`
/// asks: nothing (--quiet), the summary and where the full tables are
/// (markdown, when the report has a summary and --full was not given), or
/// the report's text in the chosen format.
void write_report(const mc::Report& report, const StdoutChoice& shown, std::optional<OutputFolderOption>& out,
                  const po::variables_map& vm);

}  // namespace insmc::app
