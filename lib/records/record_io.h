#pragma once
/// Reading and writing record files of format v1 (docs/records.md): CSV in SI
/// units after a `# insmc-record v1` line and `# key=value` header lines.
///
/// The reader is strict about content and lenient about form: it accepts
/// CRLF line endings, a UTF-8 byte-order mark, trailing blanks, blank lines,
/// header keys and columns in any order, extra columns (ignored), runs in any
/// order and interleaved (grouped by run number), and numbers written as 45,
/// 45.0, 45.000 or 4.5e1. Everything else that is wrong is an InputError
/// whose one-line message starts `FILE:LINE:COLUMN: ` (1-based).
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

#include "lib/records/record.h"

namespace insmc {

/// Caps of the reader: generous, so that a real file never meets them, and
/// small enough that a hostile or broken file is refused before it fills the
/// memory of what reads it next. For scale: 200 runs of the
/// report's 15 min test run and 90 min of navigation at 10 s are 126,000
/// rows (20 MB); one 10 h run at 100 Hz is 3.6 million rows.
/// The file: 2 GiB (a line may be long; the rows are capped below).
inline constexpr std::uint64_t kMaxRecordFileBytes = std::uint64_t{2} << 30;
/// One line: 16 KiB (a data row is ~300 bytes; header values hold file paths).
inline constexpr std::size_t kMaxRecordLineBytes = 16 * 1024;
/// Header lines: 20,000 (import-imu writes 9 per run).
inline constexpr std::size_t kMaxRecordHeaderLines = 20'000;
/// Runs in one file: 10,000 (a test campaign records tens; `simulate
/// --runs` writes at most 10,000). The gap diagnosis takes fewer in all
/// (apps/cmd_gap.cpp).
inline constexpr std::size_t kMaxRecordRuns = 10'000;
/// Rows in one run: 4 million (48 h at 23 Hz, or 11 h at 100 Hz).
inline constexpr std::size_t kMaxRecordRowsPerRun = 4'000'000;
/// Rows in the file: 4 million (104 bytes each in memory: ~420 MB, so
/// that reading and what reads next stay within 1 GB; 11 h at 100 Hz).
inline constexpr std::size_t kMaxRecordRows = 4'000'000;
/// Row values: far beyond any instrument, so that squares and sums over a
/// whole file stay finite. |f| ≤ 1e6 m/s² (10^5 g), |r| ≤ 1e16 m, |w| ≤ 1000
/// rad/s; |t_s| ≤ kMaxRunDurationS (48 h, record.h).
inline constexpr double kMaxRecordAbsFMps2 = 1e6;
inline constexpr double kMaxRecordAbsRM = 1e16;
inline constexpr double kMaxRecordAbsWRadps = 1e3;

/// Reads and validates a record file. Runs are returned in order of first
/// appearance, each with its rows in file order. Throws InputError on any
/// violation of the format: unknown version, malformed or duplicate header
/// lines, missing required keys, impossible header values, missing or
/// duplicate columns, wrong field count, non-numeric or non-finite values,
/// time not increasing within a run, phases out of order (align < test <
/// nav) or outside their time windows (align t_s < 0, test 0 ≤ t_s ≤ T, nav
/// t_s > T), r missing on a test or nav row, a run without test or nav rows,
/// no runs at all, a header value outside its physical range (record.h) or
/// inconsistent with another (the message names the key's line), a value
/// beyond the caps above, or a file, line or count beyond the caps above.
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
