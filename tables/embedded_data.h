#pragma once
/// The printed tables (tables/data/*.csv) and the cell notes
/// (tables/notes/cell_notes.csv), embedded at build time so that the built
/// binary needs no source tree. The text is the CSV file byte for byte.
#include <span>
#include <string_view>

namespace insmc::tables {

struct EmbeddedFile {
  std::string_view name;  ///< "table_3_1" … "table_5_2", "cell_notes"
  std::string_view text;  ///< the CSV, header line first
};

/// All embedded files, tables in print order, then "cell_notes".
std::span<const EmbeddedFile> embedded_files();

/// The text of one embedded file, empty if `name` is unknown.
std::string_view embedded_file(std::string_view name);

}  // namespace insmc::tables
