#include "montecarlo/report/csv.h"

#include <fmt/format.h>

#include <cmath>
#include <utility>

#include "lib/common/assert.h"

namespace insmc::mc {

std::string format_number(double x) {
  if (std::isnan(x)) return "nan";
  if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
  if (x == 0.0) return "0";
  // Every integer of magnitude below 1e15 < 2^53 is a double printed exactly.
  if (std::fabs(x) < 1e15 && x == std::trunc(x)) return fmt::format("{:.0f}", x);
  return fmt::format("{:.9g}", x);
}

Table::Table(std::vector<std::string> header) : header_(std::move(header)) {
  INSMC_ASSERT(!header_.empty(), "Table: empty header");
}

void Table::add_row(std::vector<std::string> cells) {
  INSMC_ASSERT(cells.size() == header_.size(), "Table::add_row: {} cells for {} columns",
               cells.size(), header_.size());
  rows_.push_back(std::move(cells));
}

namespace {

bool needs_quotes(const std::string& cell) {
  if (cell.find_first_of(",\"\r\n") != std::string::npos) return true;
  return !cell.empty() && (cell.front() == ' ' || cell.back() == ' ');
}

void append_cell(std::string& out, const std::string& cell) {
  if (!needs_quotes(cell)) {
    out += cell;
    return;
  }
  out += '"';
  for (const char c : cell) {
    if (c == '"') out += '"';
    out += c;
  }
  out += '"';
}

void append_line(std::string& out, const std::vector<std::string>& cells) {
  for (std::size_t i = 0; i < cells.size(); ++i) {
    if (i > 0) out += ',';
    append_cell(out, cells[i]);
  }
  out += '\n';
}

}  // namespace

std::string render_csv(const Table& table) {
  std::string out;
  append_line(out, table.header());
  for (const auto& row : table.rows()) append_line(out, row);
  return out;
}

}  // namespace insmc::mc
