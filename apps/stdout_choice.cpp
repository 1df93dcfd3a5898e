#include "apps/stdout_choice.h"

#include <fmt/format.h>

#include "apps/report_output.h"

namespace insmc::app {

void add_stdout_switches(po::options_description& opts, const std::string& full_table) {
  opts.add_options()("quiet", po::bool_switch(), "print nothing on stdout (the --out files are still written; "
                                                 "errors still go to stderr)")(
      "full", po::bool_switch(), fmt::format("--format markdown: print {} instead of the summary", full_table).c_str());
}

StdoutChoice read_stdout_choice(const po::variables_map& vm, const mc::ReportOutline& outline) {
  StdoutChoice c;
  c.format = read_report_format(vm, outline);
  c.quiet = vm["quiet"].as<bool>();
  c.full = vm["full"].as<bool>();
  return c;
}

}  // namespace insmc::app
