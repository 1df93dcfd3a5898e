#pragma once
/// A small table of strings (header row + rows) and its CSV rendering.
/// Column names carry their unit (`rms_m`).
/// The same `Table` is rendered as Markdown by montecarlo/report/markdown.h.
#include <string>
#include <vector>

namespace insmc::mc {

/// Formats a number for output tables: integral values with |x| < 1e15 are
/// printed exactly as integers ("42", "-7", "0" also for -0.0); other
/// values with fmt "{:.9g}" (nine significant digits, e.g. "0.333333333",
/// "1.5e-07"); "nan", "inf" and "-inf" for non-finite values.
std::string format_number(double x);

class Table {
 public:
  /// Header row; must not be empty.
  explicit Table(std::vector<std::string> header);

  /// Appends a row; it must have as many cells as the header (a programmer
  /// error otherwise: INSMC_ASSERT).
  void add_row(std::vector<std::string> cells);

  const std::vector<std::string>& header() const { return header_; }
  const std::vector<std::vector<std::string>>& rows() const { return rows_; }
  std::size_t column_count() const { return header_.size(); }

 private:
  std::vector<std::string> header_;
  std::vector<std::vector<std::string>> rows_;
};

/// RFC 4180 CSV: cells separated by ',', lines ended by '\n'; a cell that
/// contains ',', '"', '\r', '\n' or leading/trailing spaces is quoted, with
/// '"' doubled.
std::string render_csv(const Table& table);

}  // namespace insmc::mc
