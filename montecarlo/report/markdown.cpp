#include "montecarlo/report/markdown.h"

#include <algorithm>
#include <charconv>
#include <vector>

namespace insmc::mc {

namespace {

std::string escape_cell(const std::string& cell) {
  std::string out;
  out.reserve(cell.size());
  for (std::size_t i = 0; i < cell.size(); ++i) {
    const char c = cell[i];
    if (c == '|') {
      out += "\\|";
    } else if (c == '\r') {
      if (i + 1 < cell.size() && cell[i + 1] == '\n') continue;  // CRLF -> one break
      out += "<br>";
    } else if (c == '\n') {
      out += "<br>";
    } else {
      out += c;
    }
  }
  return out;
}

// Display width in UTF-8 code points (continuation bytes 10xxxxxx skipped).
std::size_t display_width(const std::string& s) {
  return static_cast<std::size_t>(std::count_if(
      s.begin(), s.end(), [](char c) { return (static_cast<unsigned char>(c) & 0xC0u) != 0x80u; }));
}

bool is_number(const std::string& s) {
  if (s.empty()) return false;
  double value = 0.0;
  const char* first = s.data();
  const char* last = s.data() + s.size();
  const auto [ptr, ec] = std::from_chars(first, last, value);
  return ec == std::errc() && ptr == last;
}

// A number, or a value with its interval ("28830 ± 480",
// montecarlo/report/interval_format.h): aligned like a number.
bool is_numeric_cell(const std::string& s) {
  static const std::string kPlusMinus = " ± ";
  const std::size_t at = s.find(kPlusMinus);
  if (at == std::string::npos) return is_number(s);
  return is_number(s.substr(0, at)) && is_number(s.substr(at + kPlusMinus.size()));
}

void append_padded(std::string& out, const std::string& cell, std::size_t width, bool right) {
  const std::string pad(width - display_width(cell), ' ');
  out += ' ';
  if (right) out += pad;
  out += cell;
  if (!right) out += pad;
  out += " |";
}

}  // namespace

std::string render_markdown(const Table& table) {
  const std::size_t columns = table.column_count();
  std::vector<std::string> header(columns);
  std::vector<std::vector<std::string>> rows;
  rows.reserve(table.rows().size());
  std::vector<std::size_t> width(columns, 3);  // the delimiter needs >= 3 characters
  for (std::size_t c = 0; c < columns; ++c) {
    header[c] = escape_cell(table.header()[c]);
    width[c] = std::max(width[c], display_width(header[c]));
  }
  std::vector<bool> right(columns, !table.rows().empty());
  for (const auto& row : table.rows()) {
    std::vector<std::string> escaped(columns);
    for (std::size_t c = 0; c < columns; ++c) {
      escaped[c] = escape_cell(row[c]);
      width[c] = std::max(width[c], display_width(escaped[c]));
      if (!row[c].empty() && !is_numeric_cell(row[c])) right[c] = false;  // a gap is no text
    }
    rows.push_back(std::move(escaped));
  }

  std::string out;
  out += '|';
  for (std::size_t c = 0; c < columns; ++c) append_padded(out, header[c], width[c], right[c]);
  out += "\n|";
  for (std::size_t c = 0; c < columns; ++c) {
    out += ' ';
    out += right[c] ? std::string(width[c] - 1, '-') + ':' : std::string(width[c], '-');
    out += " |";
  }
  out += '\n';
  for (const auto& row : rows) {
    out += '|';
    for (std::size_t c = 0; c < columns; ++c) append_padded(out, row[c], width[c], right[c]);
    out += '\n';
  }
  return out;
}

}  // namespace insmc::mc
