#pragma once
/// The printed values of the report's tables as transcribed once in
/// tables/data/*.csv, and the per-cell notes of tables/notes/cell_notes.csv,
/// read from the copies embedded in the binary (embedded_data.h).
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace insmc::tables {

/// One printed cell (one line of tables/data/*.csv).
struct PrintedCell {
  std::string table;         ///< "3.1" … "5.2", "4.3b"
  std::string row;           ///< the printed row, e.g. "1&2 | δf_y | U3"
  std::string column;        ///< e.g. "5 min", "bound"
  std::string unit;          ///< the printed unit
  std::string printed_text;  ///< the number as printed (×10^n written as en)
  double printed = 0.0;      ///< its value
  int printed_digits = 0;    ///< significant digits printed (0 for a printed 0)
  std::string source;        ///< line of paper/johansen-1969-RE-59.md, section, row, column
};

/// All printed cells of Tables 3.1, 4.1, 4.2, 4.3 (+ 4.3b), 5.1, 5.2, in order.
const std::vector<PrintedCell>& printed_cells();

/// Which conventions a note applies to.
enum class NoteScope { kBoth, kPaper, kCorrected };

/// One line of tables/notes/cell_notes.csv.
struct CellNote {
  std::string table;
  std::string row;     ///< a printed row (all its members) or a full member row "… [member]"
  std::string column;  ///< a printed column, or "*" for every column of the row
  NoteScope scope = NoteScope::kBoth;
  /// rounding | ocr | paper_slip | paper_approximation | time_shift |
  /// paper_error | model_difference | label | zero (tables/notes/tables.md)
  std::string kind;
  std::optional<double> meant;         ///< the value the paper meant to print (ocr, paper_slip)
  std::optional<double> alt_time_min;  ///< the time at which the paper evidently evaluated the cell
  std::string text;
};

const std::vector<CellNote>& cell_notes();

/// Records of CSV text (RFC 4180 quoting: quoted fields may hold commas,
/// quotes doubled, line breaks), header included. Throws std::runtime_error
/// naming the file on an unterminated quote.
std::vector<std::vector<std::string>> parse_csv(std::string_view text, std::string_view file_name);

/// The printed row of a cell row: "r [member]" → "r".
std::string printed_row_key(std::string_view cell_row);

/// Significant digits of a printed number text: leading zeros and the
/// trailing zeros of an integer do not count ("1440" → 3, ".015" → 2,
/// "3.0" → 2, "0" → 0).
int significant_digits(std::string_view printed_text);

/// Half a unit in the last printed place ("1.3" → 0.05, "1440" → 5,
/// "49e-3" → 0.5e-3): the largest difference rounding can explain.
double half_unit_in_last_place(std::string_view printed_text);

}  // namespace insmc::tables
