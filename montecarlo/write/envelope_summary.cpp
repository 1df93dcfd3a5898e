#include "montecarlo/write/envelope_summary.h"

#include <algorithm>
#include <fmt/format.h>

#include "montecarlo/write/csv.h"
#include "montecarlo/write/interval_format.h"
#include "montecarlo/write/markdown.h"

namespace insmc::mc {
namespace {

// The linear covariance is exact for its model; five figures resolve it to
// the metre or better at the report times without a wall of digits.
constexpr int kExactFigures = 5;

std::string cell(const HorizontalPoint& p) {
  return p.half_width ? format_with_interval(p.rms, *p.half_width) : format_significant(p.rms, kExactFigures);
}

}  // namespace

std::string render_horizontal_summary(const std::vector<HorizontalPoint>& points, const std::string& caption) {
  std::vector<double> times;
  struct Row {
    const HorizontalPoint* first;
    std::vector<std::string> cells;
  };
  std::vector<Row> rows;
  for (const HorizontalPoint& p : points) {
    if (std::find(times.begin(), times.end(), p.t_min) == times.end()) times.push_back(p.t_min);
    const auto row = std::find_if(rows.begin(), rows.end(), [&](const Row& r) {
      return r.first->scheme == p.scheme && r.first->system == p.system;
    });
    if (row == rows.end()) rows.push_back({&p, {}});
  }
  std::vector<std::string> header = {"scheme", "system", "clock"};
  for (double t : times) header.push_back(fmt::format("{} min", format_number(t)));
  header.emplace_back("ready [min]");
  Table table(header);
  for (Row& r : rows) {
    std::vector<std::string> cells = {r.first->scheme, std::to_string(r.first->system), r.first->clock};
    for (double t : times) {
      const auto p = std::find_if(points.begin(), points.end(), [&](const HorizontalPoint& q) {
        return q.scheme == r.first->scheme && q.system == r.first->system && q.t_min == t;
      });
      cells.push_back(p == points.end() ? "" : cell(*p));
    }
    cells.push_back(format_number(r.first->ready_min));
    table.add_row(std::move(cells));
  }
  return fmt::format("{}\n\n{}", caption, render_markdown(table));
}

}  // namespace insmc::mc
