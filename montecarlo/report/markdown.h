#pragma once
/// Markdown rendering of a montecarlo/report/csv.h `Table`.
#include <string>

#include "montecarlo/report/csv.h"

namespace insmc::mc {

/// GitHub-flavoured Markdown pipe table: a header row, a `---` delimiter
/// row, then the rows, each line `| a | b |` ended by '\n'. Cells are padded
/// to the column width (counted in UTF-8 code points) so the source is
/// readable; '|' in a cell is escaped as "\|" and a line break becomes
/// "<br>". Columns with at least one row whose non-empty body cells all
/// parse as numbers (std::from_chars, so also "nan" and "inf") or as a number with
/// its interval ("28830 ± 480") are right-aligned (`---:`, header
/// included), the others left-aligned.
std::string render_markdown(const Table& table);

}  // namespace insmc::mc
