// insmc tables: the report's Tables 3.1, 4.1, 4.2, 4.3, 5.1, 5.2 and the data
// of Figure 3.2, every cell computed from the model beside the printed value.
#include <cmath>
#include <cstdlib>
#include <fmt/format.h>

#include "apps/cli_common.h"
#include "apps/output_paths.h"
#include "lib/common/input_error.h"
#include "montecarlo/report/csv.h"
#include "montecarlo/report/markdown.h"
#include "montecarlo/report/plot/panel_figure.h"
#include "tables/generate.h"

namespace insmc::app {
namespace {

std::string optional_number(const std::optional<double>& v) { return v ? mc::format_number(*v) : ""; }

mc::Table cells_table(const std::vector<tables::TableCell>& cells, bool with_table_column) {
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

std::string render_markdown_report(const std::vector<tables::TableCell>& cells, tables::TableConvention conv) {
  std::string out = fmt::format(
      "# The report's tables reproduced by insmc ({} convention)\n\n"
      "`printed` is the report's value as printed; `computed` is insmc's, in the printed unit; "
      "`deviation_pct` = 100·(computed − printed)/printed. Every deviation above 3% carries a note "
      "(tables/notes/tables.md has the reasoning).\n",
      to_string(conv));
  for (std::string_view id : tables::kTableIds) {
    std::vector<tables::TableCell> part;
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
mc::PanelFigure figure_3_2(const std::vector<tables::TableCell>& cells, tables::TableConvention conv) {
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

int run_tables(const Args& args) {
  po::options_description opts("Options");
  opts.add_options()("format", po::value<std::string>()->default_value("markdown"),
                     "stdout: markdown (one table per printed table) or csv (one long table)")(
      "convention", po::value<std::string>()->default_value("paper"),
      "paper (the report's formulas as printed) or corrected (errors of the original fixed)")(
      "out", po::value<std::string>(), "folder for tables.md, tables.csv and Figure 3.2 drawn by gnuplot (fig3_2.gp/.svg/.png; created if "
                                       "needed)");
  opts.add(model_options_description());
  const auto vm = parse_args(args, "tables", "[--format markdown|csv] [--convention paper|corrected] [--out DIR]", opts);
  if (!vm) return 0;
  const OutputFormat format = parse_output_format((*vm)["format"].as<std::string>());
  if (format == OutputFormat::kJson) throw InputError("--format", "json", "tables offers markdown or csv");
  const tables::TableConvention conv =
      tables::parse_table_convention((*vm)["convention"].as<std::string>(), "--convention");
  const ModelOptions model = read_model_options(*vm, true);
  std::optional<OutputFolderOption> out =
      prepare_figure_folder(*vm, "tables", {"tables.md", "tables.csv"}, {"fig3_2"});
  const std::vector<tables::TableCell> cells = tables::compute_tables(model, conv);
  const std::string csv = mc::render_csv(cells_table(cells, true));
  const std::string md = render_markdown_report(cells, conv);
  if (out) {
    OutputFiles written{{"tables.md", md}, {"tables.csv", csv}};
    for (auto& f : mc::figure_files("fig3_2", mc::render_panel_figure(figure_3_2(cells, conv))))
      written.push_back(std::move(f));
    out->write(written);
  }
  fmt::print("{}", format == OutputFormat::kCsv ? csv : md);
  return 0;
}

}  // namespace insmc::app
