#pragma once
/// What `insmc run` and `insmc covariance` print on stdout: by default a
/// compact summary (montecarlo/study/write/envelope_summary.h) and where the full
/// tables are; --full the full table; --quiet nothing (the files are still
/// written, errors still go to stderr); --format csv|json the machine output
/// alone, unchanged, for scripts.
#include <string>
#include <vector>

#include "apps/cli_common.h"

namespace insmc::app {

struct StdoutChoice {
  mc::ReportFormat format = mc::ReportFormat::kMarkdown;
  bool quiet = false;  ///< nothing on stdout
  bool full = false;   ///< markdown: the full table instead of the summary
};

/// --quiet and --full (`full_table`: what --full prints).
void add_stdout_switches(po::options_description& opts, const std::string& full_table);

/// --format (one `outline` offers), --quiet, --full.
StdoutChoice read_stdout_choice(const po::variables_map& vm, const mc::ReportOutline& outline);

}  // namespace insmc::app
