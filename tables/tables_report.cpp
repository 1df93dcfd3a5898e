#include "tables/tables_report.h"

#include <cmath>
#include <fmt/format.h>

#include "montecarlo/report/csv.h"
#include "montecarlo/report/markdown.h"
#include "montecarlo/report/plot/panel_figure.h"

namespace insmc::tables {
namespace {

std::string optional_number(const std::optional<double>& v) { return v ? mc::format_number(*v) : ""; }

mc::Table cells_table(const std::vector<TableCell>& cells, bool with_table_column) {
  std::vector<std::string> header = {"row", "column", "unit", "printed", "computed", "deviation_pct", "note"};
  if (with_table_column) header.insert(header.begin(), "table");
  mc::Table t(header);
  for (const auto& c : cells) {
    std::vector<std::string> row = {c.row, c.column, c.unit, optional_number(c.printed),
                                    mc::format_number(c.computed), optional_number(c.deviation_pct), c.note};
    if (with_table_column) row.insert(row.begin(), c.table);
    t.add_row(row);
  }
  return t;
}

std::string render_markdown_report(const std::vector<TableCell>& cells, TableConvention conv) {
  std::string out = fmt::format(
      "# The report's tables reproduced by insmc ({} convention)\n\n"
      "`printed` is the report's value as printed; `computed` is insmc's, in the printed unit; "
      "`deviation_pct` = 100·(computed − printed)/printed. Every deviation above 3% carries a note "
      "(tables/notes/tables.md has the reasoning).\n",
      to_string(conv));
  for (std::string_view id : kTableIds) {
    std::vector<TableCell> part;
    for (const auto& c : cells)
      if (c.table == id) part.push_back(c);
    if (part.empty()) continue;
    out += fmt::format("\n## {}\n\n{}", id == "fig3.2" ? "Figure 3.2 (data)" : fmt::format("Table {}", id),
                       mc::render_markdown(cells_table(part, false)));
  }
  return out;
}

/// Figure 3.2 drawn again from its data: the position error per unit of each
/// term of (3.29) against time, magnitudes on a log axis (the cells keep
/// their signs).
mc::PanelFigure figure_3_2(const std::vector<TableCell>& cells, TableConvention conv) {
  mc::PanelFigure f;
  f.stem = "fig3_2";
  f.title = fmt::format("Figure 3.2: position error propagation, per unit of each term of (3.29) ({} convention)",
                        to_string(conv));
  f.x_label = "time since the switch-over [min]";
  f.y_label = "|position error| per unit [ft]";
  f.log_y = true;
  f.columns = 1;
  mc::PlotPanel panel;
  panel.title = "uncompensated run under 1.5 h";
  for (const auto& c : cells) {
    if (c.table != "fig3.2") continue;
    if (panel.lines.empty() || panel.lines.back().name != c.row)
      panel.lines.push_back({c.row, {}, {}, {}, {}, {}, static_cast<int>(panel.lines.size()), false, false});
    if (c.time_min && std::abs(c.computed) > 0) {  // the log axis has no 0 (every term is 0 at t = 0)
      panel.lines.back().x.push_back(*c.time_min);
      panel.lines.back().y.push_back(std::abs(c.computed));
    }
  }
  f.panels.push_back(std::move(panel));
  return f;
}

}  // namespace

mc::ReportOutline tables_report_outline() {
  return {"tables", {"tables.md", "tables.csv"}, {"fig3_2"}, {mc::ReportFormat::kMarkdown, mc::ReportFormat::kCsv}};
}

mc::Report tables_report(const std::vector<TableCell>& cells, TableConvention conv) {
  mc::Report report(tables_report_outline());
  report.file("tables.md", render_markdown_report(cells, conv))
      .file("tables.csv", mc::render_csv(cells_table(cells, true)))
      // Figure 3.2's data too only when the set is written.
      .figure("fig3_2", [cells, conv] { return mc::render_panel_figure(figure_3_2(cells, conv)); })
      .shown_file(mc::ReportFormat::kMarkdown, "tables.md")
      .shown_file(mc::ReportFormat::kCsv, "tables.csv");
  return report;
}

}  // namespace insmc::tables
