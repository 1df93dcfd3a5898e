#include "apps/report_output.h"

#include <fmt/format.h>

#include "lib/common/input_error.h"

namespace insmc::app {

mc::ReportFormat read_report_format(const po::variables_map& vm, const mc::ReportOutline& outline) {
  const std::string text = vm["format"].as<std::string>();
  for (const mc::ReportFormat format : outline.formats)
    if (text == mc::format_name(format) || (format == mc::ReportFormat::kMarkdown && text == "md")) return format;
  throw InputError("--format", echo_input(text), fmt::format("{} prints {}", outline.command, outline.offered_text()));
}

void write_report(const mc::Report& report, const StdoutChoice& shown, std::optional<OutputFolderOption>& out,
                  const po::variables_map& vm) {
  if (out) out->write(report.draw_set());
  if (shown.quiet) return;
  const auto& summary = report.summary();
  if (shown.format != mc::ReportFormat::kMarkdown || !summary) {
    fmt::print("{}", report.shown(shown.format));
    return;
  }
  const std::string line = summary->where_the_rest_is(
      vm.count("out") ? std::optional<std::string>(vm["out"].as<std::string>()) : std::nullopt);
  if (!shown.full) {
    fmt::print("{}\n{}", summary->text, line);
    return;
  }
  // --full shows the full tables; where their files are still helps.
  fmt::print("{}", report.shown(shown.format));
  if (out) fmt::print("\n{}", line);
}

}  // namespace insmc::app
