#pragma once
/// Reading and writing record files of format v1 (DESIGN.md §3): CSV in SI
/// units after a `# insmc-record v1` line and `# key=value` header lines.
///
/// The reader is strict about content and lenient about form: it accepts
/// CRLF line endings, a UTF-8 byte-order mark, trailing blanks, blank lines,
/// header keys and columns in any order, extra columns (ignored), runs in any
/// order and interleaved (grouped by run number), and numbers written as 45,
/// 45.0, 45.000 or 4.5e1. Everything else that is wrong is an InputError
/// whose one-line message starts `FILE:LINE:COLUMN: ` (1-based).
#include <filesystem>
#include <string>
#include <string_view>

#include "lib/records/record.h"

namespace insmc {

/// Reads and validates a record file. Runs are returned in order of first
/// appearance, each with its rows in file order. Throws InputError on any
/// violation of the format: unknown version, malformed or duplicate header
/// lines, missing required keys, impossible header values, missing or
/// duplicate columns, wrong field count, non-numeric or non-finite values,
/// time not increasing within a run, phases out of order (align < test <
/// nav) or outside their time windows (align t_s < 0, test 0 ≤ t_s ≤ T, nav
/// t_s > T), r missing on a test or nav row, a run without test or nav rows,
/// or no runs at all.
RecordFile read_record_file(const std::filesystem::path& path);

/// As read_record_file, on text already in memory; `source_name` stands for
/// the file name in messages.
RecordFile parse_record_text(std::string_view text, std::string_view source_name);

/// Whether the writer keeps the simulator's `truth.` header keys.
enum class TruthKeys { kKeep, kStrip };

/// The text of a record file holding `file`. Numbers are written in the
/// shortest form that reads back to the same bits (fmt "{}"), so
/// parse_record_text(write_record_file(x)) == x for every valid x (what the
/// reader accepts). The w columns are written only when some row has a w
/// value. Precondition (asserted): `file` is valid as the reader defines it.
std::string write_record_file(const RecordFile& file, TruthKeys truth = TruthKeys::kKeep);

}  // namespace insmc
