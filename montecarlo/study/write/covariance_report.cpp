#include "montecarlo/study/write/covariance_report.h"

#include <fmt/format.h>

#include "montecarlo/report/plot/bar_figure.h"
#include "montecarlo/study/write/sensitivity_table.h"
#include "montecarlo/study/write/study_writer.h"

namespace insmc::mc {

ReportOutline covariance_report_outline() {
  return {"covariance",
          {"covariance.csv", "covariance_grid.csv", "budget.csv", "sensitivity.csv", "covariance.md"},
          {"budget"}};
}

Report covariance_report(const StudyConfig& config, const StudyLayout& layout, const StudyMap& map, LengthUnit unit) {
  CovarianceFiles files = render_covariance(config, layout, map, unit);
  Json json = Json::object();
  json["settings"] = settings_json(config, SettingsOf::kCovariance);
  json["covariance"] = std::move(files.covariance_json);
  Report report(covariance_report_outline());
  report.file("covariance.csv", std::move(files.covariance_csv))
      .file("covariance_grid.csv", std::move(files.covariance_grid_csv))
      .file("budget.csv", std::move(files.budget_csv))
      .file("sensitivity.csv", render_sensitivity_csv(layout, map))
      .file("covariance.md", std::move(files.covariance_md))
      .figure("budget", [plot = std::move(files.budget_plot)] { return render_bar_figure(plot); })
      .shown_file(ReportFormat::kMarkdown, "covariance.md")
      .shown_file(ReportFormat::kCsv, "covariance.csv")
      .shown(ReportFormat::kJson, json.dump())
      .summary({fmt::format("insmc covariance: fidelity {}\n\n{}", to_string(config.fidelity), files.summary_text),
                [](const std::optional<std::string>& out) {
                  return full_tables_line("covariance", {"covariance.md", "covariance.csv"}, out);
                }});
  return report;
}

}  // namespace insmc::mc
