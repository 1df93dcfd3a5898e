#include "tables/printed.h"

#include <charconv>
#include <cmath>
#include <stdexcept>
#include <system_error>

#include "tables/embedded_data.h"

namespace insmc::tables {
namespace {

/// Splits CSV text into records of fields (RFC 4180: fields may be quoted,
/// "" inside quotes is a quote, quoted fields may hold commas).
std::vector<std::vector<std::string>> split_csv(std::string_view text, std::string_view file) {
  std::vector<std::vector<std::string>> records;
  std::vector<std::string> fields;
  std::string field;
  bool quoted = false, any = false;
  int line = 1;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (quoted) {
      if (c == '"') {
        if (i + 1 < text.size() && text[i + 1] == '"') {
          field += '"';
          ++i;
        } else {
          quoted = false;
        }
      } else {
        if (c == '\n') ++line;
        field += c;
      }
      continue;
    }
    if (c == '"') {
      quoted = true;
      any = true;
    } else if (c == ',') {
      fields.push_back(std::move(field));
      field.clear();
      any = true;
    } else if (c == '\n' || c == '\r') {
      if (c == '\r' && i + 1 < text.size() && text[i + 1] == '\n') ++i;
      if (any || !field.empty()) {
        fields.push_back(std::move(field));
        records.push_back(std::move(fields));
      }
      fields.clear();
      field.clear();
      any = false;
      ++line;
    } else {
      field += c;
      any = true;
    }
  }
  if (quoted) throw std::runtime_error(std::string(file) + ": unterminated quote at line " + std::to_string(line));
  if (any || !field.empty()) {
    fields.push_back(std::move(field));
    records.push_back(std::move(fields));
  }
  return records;
}

double parse_number(const std::string& s, std::string_view file, std::size_t line, std::string_view what) {
  double v = 0.0;
  const char* first = s.data();
  const char* last = s.data() + s.size();
  if (!s.empty() && s[0] == '+') ++first;
  const auto [ptr, ec] = std::from_chars(first, last, v);
  if (ec != std::errc() || ptr != last || !std::isfinite(v))
    throw std::runtime_error(std::string(file) + " line " + std::to_string(line) + ": " +
                             std::string(what) + " '" + s + "' is not a number");
  return v;
}

/// Checks the header and returns the data records with their 1-based line numbers.
std::vector<std::pair<std::size_t, std::vector<std::string>>> records_after_header(
    std::string_view text, std::string_view file, const std::vector<std::string_view>& header) {
  const auto records = split_csv(text, file);
  if (records.empty()) throw std::runtime_error(std::string(file) + ": empty");
  if (records[0].size() != header.size())
    throw std::runtime_error(std::string(file) + ": header must have " + std::to_string(header.size()) + " fields");
  for (std::size_t i = 0; i < header.size(); ++i)
    if (records[0][i] != header[i])
      throw std::runtime_error(std::string(file) + ": header field " + std::to_string(i + 1) + " must be " +
                               std::string(header[i]));
  std::vector<std::pair<std::size_t, std::vector<std::string>>> out;
  for (std::size_t r = 1; r < records.size(); ++r) {
    if (records[r].size() != header.size())
      throw std::runtime_error(std::string(file) + " record " + std::to_string(r + 1) + ": expected " +
                               std::to_string(header.size()) + " fields, got " +
                               std::to_string(records[r].size()));
    out.emplace_back(r + 1, records[r]);
  }
  return out;
}

}  // namespace

std::vector<std::vector<std::string>> parse_csv(std::string_view text, std::string_view file) {
  return split_csv(text, file);
}

namespace {

/// The embedded printed-cell CSV (and below, the cell notes' CSV). Throws
/// std::runtime_error naming the file and line on malformed data.
std::vector<PrintedCell> parse_printed_csv(std::string_view text, std::string_view file) {
  std::vector<PrintedCell> out;
  for (auto& [line, f] : records_after_header(
           text, file, {"table", "row", "column", "unit", "printed", "printed_digits", "source"})) {
    PrintedCell c;
    c.table = f[0];
    c.row = f[1];
    c.column = f[2];
    c.unit = f[3];
    c.printed_text = f[4];
    c.printed = parse_number(f[4], file, line, "printed");
    c.printed_digits = static_cast<int>(parse_number(f[5], file, line, "printed_digits"));
    c.source = f[6];
    out.push_back(std::move(c));
  }
  return out;
}

std::vector<CellNote> parse_cell_notes_csv(std::string_view text, std::string_view file) {
  std::vector<CellNote> out;
  for (auto& [line, f] : records_after_header(
           text, file, {"table", "row", "column", "convention", "kind", "meant", "alt_time_min", "note"})) {
    CellNote n;
    n.table = f[0];
    n.row = f[1];
    n.column = f[2];
    if (f[3] == "both") {
      n.scope = NoteScope::kBoth;
    } else if (f[3] == "paper") {
      n.scope = NoteScope::kPaper;
    } else if (f[3] == "corrected") {
      n.scope = NoteScope::kCorrected;
    } else {
      throw std::runtime_error(std::string(file) + " line " + std::to_string(line) +
                               ": convention must be both, paper or corrected");
    }
    n.kind = f[4];
    if (!f[5].empty()) n.meant = parse_number(f[5], file, line, "meant");
    if (!f[6].empty()) n.alt_time_min = parse_number(f[6], file, line, "alt_time_min");
    n.text = f[7];
    out.push_back(std::move(n));
  }
  return out;
}

}  // namespace

const std::vector<PrintedCell>& printed_cells() {
  static const std::vector<PrintedCell> cells = [] {
    std::vector<PrintedCell> all;
    for (const auto& f : embedded_files()) {
      if (f.name == "cell_notes") continue;
      auto part = parse_printed_csv(f.text, f.name);
      all.insert(all.end(), part.begin(), part.end());
    }
    return all;
  }();
  return cells;
}

const std::vector<CellNote>& cell_notes() {
  static const std::vector<CellNote> notes = parse_cell_notes_csv(embedded_file("cell_notes"), "cell_notes");
  return notes;
}

std::string printed_row_key(std::string_view row) {
  if (!row.empty() && row.back() == ']') {
    const auto open = row.rfind(" [");
    if (open != std::string_view::npos) return std::string(row.substr(0, open));
  }
  return std::string(row);
}

namespace {

struct NumberParts {
  std::string mantissa;  ///< without sign
  int exponent = 0;
};

NumberParts split_number(std::string_view text) {
  NumberParts p;
  std::string_view s = text;
  if (!s.empty() && (s[0] == '+' || s[0] == '-')) s.remove_prefix(1);
  const auto e = s.find_first_of("eE");
  p.mantissa = std::string(s.substr(0, e));
  if (e != std::string_view::npos) {
    std::string_view ex = s.substr(e + 1);
    if (!ex.empty() && ex[0] == '+') ex.remove_prefix(1);
    std::from_chars(ex.data(), ex.data() + ex.size(), p.exponent);
  }
  return p;
}

}  // namespace

int significant_digits(std::string_view text) {
  const NumberParts p = split_number(text);
  std::string d;
  const bool has_point = p.mantissa.find('.') != std::string::npos;
  for (char c : p.mantissa)
    if (c != '.') d += c;
  const auto first = d.find_first_not_of('0');
  if (first == std::string::npos) return 0;
  d = d.substr(first);
  if (!has_point) {
    const auto last = d.find_last_not_of('0');
    d = d.substr(0, last + 1);
  }
  return static_cast<int>(d.size());
}

double half_unit_in_last_place(std::string_view text) {
  const NumberParts p = split_number(text);
  const auto point = p.mantissa.find('.');
  int last_place = 0;  // power of ten of the last significant printed digit
  if (point != std::string::npos) {
    last_place = -static_cast<int>(p.mantissa.size() - point - 1);
  } else {
    const auto last = p.mantissa.find_last_not_of('0');
    last_place = last == std::string::npos ? 0 : static_cast<int>(p.mantissa.size() - last - 1);
  }
  return 0.5 * std::pow(10.0, last_place + p.exponent);
}

}  // namespace insmc::tables
