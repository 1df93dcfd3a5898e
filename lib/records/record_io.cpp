#include "lib/records/record_io.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <optional>
#include <sstream>
#include <unordered_map>
#include <vector>

#include "lib/common/assert.h"
#include "lib/common/input_error.h"
#include "lib/common/input_text.h"
#include "lib/records/number_text.h"

namespace insmc {
namespace {

using records_detail::NumberStatus;
using records_detail::parse_double;
using records_detail::parse_int64;

constexpr std::string_view kVersionLine = "# insmc-record v1";
constexpr std::string_view kMagic = "insmc-record";
constexpr std::string_view kVersion = "v1";
constexpr std::string_view kBom = "\xEF\xBB\xBF";

enum Column : int { kRun, kT, kPhase, kFx, kFy, kFz, kRx, kRy, kRz, kWx, kWy, kWz, kColumnCount };
constexpr std::array<std::string_view, kColumnCount> kColumnNames = {
    "run", "t_s", "phase", "f_x", "f_y", "f_z", "r_x", "r_y", "r_z", "w_x", "w_y", "w_z"};
constexpr int kRequiredColumnCount = kWx;  // run … r_z
constexpr std::string_view kRequiredColumnsText = "run,t_s,phase,f_x,f_y,f_z,r_x,r_y,r_z";

/// File names in messages: shown whole up to this length (escaped).
constexpr std::size_t kMaxShownPathBytes = 256;

/// A field's text, cut to a readable length with control bytes escaped, so
/// that every message stays on one line.
std::string quote(std::string_view text) { return fmt::format("'{}'", echo_input(text)); }

/// What is wrong with a row, and in which column (for the reader's column
/// number); shared by the reader and the writer's precondition check.
struct RowProblem {
  Column column;
  std::string message;
};

/// The rules that tie the rows of one run together and to the header.
class RunChecker {
 public:
  std::optional<RowProblem> check(const RecordRow& row, double test_duration_s) {
    if (!std::isfinite(row.t_s)) return RowProblem{kT, fmt::format("t_s = {}: not finite", row.t_s)};
    if (!(std::abs(row.t_s) <= kMaxRunDurationS)) {
      return RowProblem{kT, fmt::format("t_s = {}: must lie in [-{}, {}] (a run lasts at most {} h)", row.t_s,
                                        kMaxRunDurationS, kMaxRunDurationS, kMaxRunDurationS / 3600)};
    }
    if (seen_ && static_cast<int>(row.phase) < static_cast<int>(last_phase_)) {
      return RowProblem{kPhase, fmt::format("phase '{}' after '{}' in run {}: phases must come in the order "
                                            "align, test, nav",
                                            to_string(row.phase), to_string(last_phase_), row.run)};
    }
    if (seen_ && !(row.t_s > last_t_s_)) {
      return RowProblem{kT, fmt::format("t_s = {} is not after the previous row of run {} (t_s = {}): time must "
                                        "increase within a run",
                                        row.t_s, row.run, last_t_s_)};
    }
    switch (row.phase) {
      case Phase::kAlign:
        if (!(row.t_s < 0.0)) {
          return RowProblem{kT, fmt::format("t_s = {} on an align row: alignment rows need t_s < 0", row.t_s)};
        }
        break;
      case Phase::kTest:
        // The last test row may be stamped past T by a recorder's jitter: up
        // to kTestEndJitter of its spacing from the row before.
        if (!(row.t_s >= 0.0 && (row.t_s <= test_duration_s ||
                                 (seen_ && last_phase_ == Phase::kTest &&
                                  row.t_s - test_duration_s <= kTestEndJitter * (row.t_s - last_t_s_))))) {
          return RowProblem{kT, fmt::format("t_s = {} on a test row: test rows need 0 <= t_s <= test_duration_s "
                                            "= {}",
                                            row.t_s, test_duration_s)};
        }
        break;
      case Phase::kNav:
        if (!(row.t_s > test_duration_s)) {
          return RowProblem{kT, fmt::format("t_s = {} on a nav row: nav rows need t_s > test_duration_s = {}",
                                            row.t_s, test_duration_s)};
        }
        break;
    }
    if (row.phase != Phase::kAlign && !row.r_ap_m) {
      return RowProblem{kRx, fmt::format("r_x, r_y, r_z are empty on a {} row: r is required on test and nav rows",
                                         to_string(row.phase))};
    }
    const auto beyond = [&](Column c, double v, double cap, const char* unit) {
      return RowProblem{c, fmt::format("{} = {}: |{}| must be at most {} ({})", kColumnNames[c], v,
                                       kColumnNames[c].substr(0, 1), cap, unit)};
    };
    for (int k = 0; k < 3; ++k) {
      if (row.f_mps2[k] && !(std::abs(*row.f_mps2[k]) <= kMaxRecordAbsFMps2))
        return beyond(Column(kFx + k), *row.f_mps2[k], kMaxRecordAbsFMps2, "m/s2");
      if (row.w_radps[k] && !(std::abs(*row.w_radps[k]) <= kMaxRecordAbsWRadps))
        return beyond(Column(kWx + k), *row.w_radps[k], kMaxRecordAbsWRadps, "rad/s");
      if (row.r_ap_m && !(std::abs((*row.r_ap_m)[k]) <= kMaxRecordAbsRM))
        return beyond(Column(kRx + k), (*row.r_ap_m)[k], kMaxRecordAbsRM, "m");
    }
    seen_ = true;
    last_t_s_ = row.t_s;
    last_phase_ = row.phase;
    if (row.phase != Phase::kAlign) has_test_or_nav_ = true;
    return std::nullopt;
  }
  bool has_test_or_nav() const { return has_test_or_nav_; }

 private:
  bool seen_ = false;
  bool has_test_or_nav_ = false;
  double last_t_s_ = 0.0;
  Phase last_phase_ = Phase::kAlign;
};

struct Field {
  std::string_view text;  ///< trimmed, surrounding double quotes removed
  std::size_t column;     ///< 1-based column of the field's first byte
};

/// Splits a line at commas (no quoted commas: record fields are numbers and
/// names).
void split_fields(std::string_view line, std::vector<Field>& out) {
  out.clear();
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = line.find(',', start);
    const std::size_t end = comma == std::string_view::npos ? line.size() : comma;
    std::string_view text = trim(line.substr(start, end - start));
    if (text.size() >= 2 && text.front() == '"' && text.back() == '"') text = trim(text.substr(1, text.size() - 2));
    out.push_back(Field{text, start + 1});
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
}

class Parser {
 public:
  Parser(ByteSource source, std::string_view source_name)
      : lines_(std::move(source), kMaxRecordLineBytes), name_(echo_input(source_name, kMaxShownPathBytes)) {}

  RecordFile parse() {
    RecordFile file;
    parse_version();
    std::string_view line;
    bool have_columns = false;
    while (next_line(line)) {
      if (line.empty()) continue;
      if (line.front() == '#') {
        parse_header_line(line, file.header);
        continue;
      }
      check_required_keys(file.header);
      check_consistency(file.header);
      parse_column_header(line);
      have_columns = true;
      break;
    }
    if (!have_columns) {
      check_required_keys(file.header);
      fail(line_number_ + 1, 1,
           fmt::format("missing the column header line: after the '# key=value' lines a line must name the "
                       "columns {} (any order)",
                       kRequiredColumnsText));
    }
    test_duration_s_ = file.header.test_duration_s();
    parse_rows(file);
    return file;
  }

 private:
  [[noreturn]] void fail(std::size_t line, std::size_t column, const std::string& message) const {
    throw InputError(fmt::format("{}:{}:{}: {}", name_, line, column, message));
  }

  /// Column (1-based) of `part`, a view into the current line.
  std::size_t column_of(std::string_view part) const {
    return static_cast<std::size_t>(part.data() - line_.data()) + 1;
  }

  /// Next physical line without its line ending and trailing blanks.
  bool next_line(std::string_view& line) {
    std::string_view raw;
    const bool got = lines_.next(raw, [&](std::size_t length, bool measured_all) {
      fail(line_number_ + 1, kMaxRecordLineBytes + 1,
           fmt::format("line of {}{} bytes: a record line may hold at most {} bytes", measured_all ? "" : "more than ",
                       length, kMaxRecordLineBytes));
    });
    if (!got) return false;
    ++line_number_;
    if (line_number_ == 1 && raw.starts_with(kBom)) raw.remove_prefix(kBom.size());
    line_ = trim_right(raw);
    line = line_;
    return true;
  }

  void parse_version() {
    std::string_view line;
    const std::string expected = fmt::format("the first line must be '{}'", kVersionLine);
    if (!next_line(line)) fail(1, 1, fmt::format("empty file: {}", expected));
    if (line.starts_with('#')) {
      const std::string_view rest = trim_left(line.substr(1));
      if (rest.starts_with(kMagic) && (rest.size() == kMagic.size() || is_blank(rest[kMagic.size()]))) {
        const std::string_view version = trim_left(rest.substr(kMagic.size()));
        if (version == kVersion) return;
        if (version.empty()) fail(1, line.size() + 1, fmt::format("missing format version: {}", expected));
        fail(1, column_of(version),
             fmt::format("unsupported record format version {}: this reader reads {} ('{}')", quote(version),
                         kVersion, kVersionLine));
      }
    }
    fail(1, 1, fmt::format("not an insmc record file: {} (found {})", expected, quote(line)));
  }

  void parse_header_line(std::string_view line, RecordHeader& header) {
    const std::string_view content = trim_left(line.substr(1));
    const std::size_t eq = content.find('=');
    if (content.empty() || eq == std::string_view::npos) {
      fail(line_number_, content.empty() ? 1 : column_of(content),
           fmt::format("header line {} is not '# key=value'", quote(line)));
    }
    const std::string_view key = trim_right(content.substr(0, eq));
    const std::string_view value = trim(content.substr(eq + 1));
    // A control byte inside a key or value (a lone CR, a NUL) would be a line
    // break or worse to other tools, and the writer could not keep it.
    for (const std::string_view part : {key, value}) {
      const auto bad = std::find_if(part.begin(), part.end(), [](char c) {
        return (static_cast<unsigned char>(c) < 0x20 && c != '\t') || c == 0x7F;
      });
      if (bad != part.end()) {
        fail(line_number_, column_of(part) + static_cast<std::size_t>(bad - part.begin()),
             fmt::format("control character '{}' in the header line {}: keys and values are text on one line",
                         echo_input(std::string_view(&*bad, 1)), quote(line)));
      }
    }
    if (key.empty()) fail(line_number_, column_of(content), "header line has an empty key before '='");
    if (header_lines_.size() >= kMaxRecordHeaderLines) {
      fail(line_number_, 1,
           fmt::format("more than {} header lines: a record file may hold at most {}", kMaxRecordHeaderLines,
                       kMaxRecordHeaderLines));
    }
    const auto [it, inserted] = header_lines_.emplace(std::string(key), line_number_);
    if (!inserted) {
      fail(line_number_, column_of(key),
           fmt::format("duplicate header key {} (first given on line {})", quote(key), it->second));
    }
    if (auto problem = header_value_problem(key, value)) {
      fail(line_number_, value.empty() ? column_of(content) + eq + 1 : column_of(value),
           fmt::format("header {} = {}: {}", echo_input(key), quote(value), *problem));
    }
    header.set(key, std::string(value));
  }

  void check_required_keys(const RecordHeader& header) const {
    for (std::string_view key : kRequiredHeaderKeys) {
      if (header.find(key) == nullptr) {
        fail(line_number_, 1,
             fmt::format("missing required header key '{}' (a '# {}=...' line before the column header; "
                         "required: latitude_deg, system, test_duration_s, scheme)",
                         key, key));
      }
    }
  }

  /// Values that are each in range but impossible together: blamed on the
  /// line of the key at fault.
  void check_consistency(const RecordHeader& header) const {
    if (const std::optional<HeaderProblem> p = header_consistency_problem(header)) {
      const auto it = header_lines_.find(p->key);
      fail(it != header_lines_.end() ? it->second : line_number_, 1,
           fmt::format("header {}: {}", p->key, p->message));
    }
  }

  void parse_column_header(std::string_view line) {
    split_fields(line, fields_);
    column_count_ = fields_.size();
    index_.fill(-1);
    for (std::size_t i = 0; i < fields_.size(); ++i) {
      for (int c = 0; c < kColumnCount; ++c) {
        if (fields_[i].text != kColumnNames[c]) continue;
        if (index_[c] >= 0) {
          fail(line_number_, fields_[i].column,
               fmt::format("duplicate column '{}' (also column {} of the header)", kColumnNames[c],
                           fields_[index_[c]].column));
        }
        index_[c] = static_cast<int>(i);
      }
    }
    std::string missing;
    for (int c = 0; c < kRequiredColumnCount; ++c) {
      if (index_[c] < 0) missing = missing.empty() ? std::string(kColumnNames[c])
                                                   : fmt::format("{}, {}", missing, kColumnNames[c]);
    }
    if (!missing.empty()) {
      fail(line_number_, 1,
           fmt::format("missing column(s) {}: the column header must contain {} in any order (w_x, w_y, w_z "
                       "optional, other columns ignored)",
                       missing, kRequiredColumnsText));
    }
    columns_line_ = line_number_;
  }

  const Field* field(Column c) const { return index_[c] < 0 ? nullptr : &fields_[index_[c]]; }

  std::optional<double> optional_number(Column c) const {
    const Field* f = field(c);
    if (f == nullptr || f->text.empty()) return std::nullopt;
    double v = 0.0;
    const NumberStatus status = parse_double(f->text, v);
    if (status != NumberStatus::kOk) {
      fail(line_number_, f->column, fmt::format("{} = {}: {}", kColumnNames[c], quote(f->text), describe(status)));
    }
    return v;
  }

  double required_number(Column c) const {
    const Field* f = field(c);
    if (f->text.empty()) fail(line_number_, f->column, fmt::format("{} is empty: it is required", kColumnNames[c]));
    return *optional_number(c);
  }

  RecordRow parse_row(std::string_view line) {
    split_fields(line, fields_);
    if (fields_.size() != column_count_) {
      const std::size_t column =
          fields_.size() > column_count_ ? fields_[column_count_].column - 1 : line.size() + 1;
      fail(line_number_, column,
           fmt::format("{} fields, but the column header (line {}) has {}", fields_.size(), columns_line_,
                       column_count_));
    }
    RecordRow row;
    const Field* run = field(kRun);
    if (run->text.empty()) fail(line_number_, run->column, "run is empty: it is required");
    const NumberStatus run_status = parse_int64(run->text, row.run);
    if (run_status != NumberStatus::kOk) {
      fail(line_number_, run->column,
           fmt::format("run = {}: {} (run numbers are integers)", quote(run->text), describe(run_status)));
    }
    row.t_s = required_number(kT);
    const Field* phase = field(kPhase);
    if (phase->text == "align") {
      row.phase = Phase::kAlign;
    } else if (phase->text == "test") {
      row.phase = Phase::kTest;
    } else if (phase->text == "nav") {
      row.phase = Phase::kNav;
    } else {
      fail(line_number_, phase->column,
           fmt::format("phase = {}: must be one of: align, test, nav", quote(phase->text)));
    }
    for (int k = 0; k < 3; ++k) {
      row.f_mps2[k] = optional_number(Column(kFx + k));
      row.w_radps[k] = optional_number(Column(kWx + k));
    }
    std::array<std::optional<double>, 3> r;
    for (int k = 0; k < 3; ++k) r[k] = optional_number(Column(kRx + k));
    if (r[0] && r[1] && r[2]) {
      row.r_ap_m = Eigen::Vector3d(*r[0], *r[1], *r[2]);
    } else if (r[0] || r[1] || r[2]) {
      const int empty = !r[0] ? 0 : !r[1] ? 1 : 2;
      const int given = r[0] ? 0 : r[1] ? 1 : 2;
      fail(line_number_, field(Column(kRx + empty))->column,
           fmt::format("{} is empty but {} is not: r_x, r_y, r_z must be all present or all empty",
                       kColumnNames[kRx + empty], kColumnNames[kRx + given]));
    }
    return row;
  }

  void parse_rows(RecordFile& file) {
    struct RunState {
      RunChecker checker;
      std::size_t first_line = 0;
      std::size_t first_column = 1;  ///< of the run field on that line
    };
    std::unordered_map<std::int64_t, std::size_t> run_index;
    std::vector<RunState> states;
    std::size_t total_rows = 0;
    std::string_view line;
    while (next_line(line)) {
      if (line.empty()) continue;
      if (line.front() == '#') {
        fail(line_number_, 1,
             fmt::format("header line after the column header (line {}): '# key=value' lines come first",
                         columns_line_));
      }
      RecordRow row = parse_row(line);
      if (++total_rows > kMaxRecordRows) {
        fail(line_number_, 1,
             fmt::format("more than {} data rows: a record file may hold at most {} (split it into several files)",
                         kMaxRecordRows, kMaxRecordRows));
      }
      const auto [it, inserted] = run_index.emplace(row.run, file.runs.size());
      if (inserted && file.runs.size() >= kMaxRecordRuns) {
        fail(line_number_, field(kRun)->column,
             fmt::format("run {} is run number {} of the file: a record file may hold at most {} runs", row.run,
                         file.runs.size() + 1, kMaxRecordRuns));
      }
      if (!inserted && file.runs[it->second].rows.size() >= kMaxRecordRowsPerRun) {
        fail(line_number_, field(kRun)->column,
             fmt::format("run {} has more than {} rows: a run may hold at most {}", row.run, kMaxRecordRowsPerRun,
                         kMaxRecordRowsPerRun));
      }
      if (inserted) {
        file.runs.push_back(RecordRun{row.run, {}});
        states.push_back(RunState{RunChecker{}, line_number_, field(kRun)->column});
      }
      if (auto problem = states[it->second].checker.check(row, test_duration_s_)) {
        const Field* f = field(problem->column);
        fail(line_number_, f != nullptr ? f->column : 1, problem->message);
      }
      file.runs[it->second].rows.push_back(std::move(row));
    }
    if (file.runs.empty()) {
      fail(line_number_ + 1, 1,
           fmt::format("no data rows after the column header (line {}): a record file needs at least one run",
                       columns_line_));
    }
    for (std::size_t i = 0; i < file.runs.size(); ++i) {
      if (!states[i].checker.has_test_or_nav()) {
        fail(states[i].first_line, states[i].first_column,
             fmt::format("run {} has only align rows: every run needs test or nav rows", file.runs[i].id));
      }
    }
    // Runs in the order of their numbers, not of the file's lines: what is
    // drawn per run (the null runs' streams) follows the run, so the same
    // runs written in another order give the same results.
    std::sort(file.runs.begin(), file.runs.end(),
              [](const RecordRun& a, const RecordRun& b) { return a.id < b.id; });
  }

  LineReader lines_;
  std::string name_;
  std::size_t line_number_ = 0;
  std::string_view line_;
  std::unordered_map<std::string, std::size_t> header_lines_;
  std::vector<Field> fields_;
  std::array<int, kColumnCount> index_{};
  std::size_t column_count_ = 0;
  std::size_t columns_line_ = 0;
  double test_duration_s_ = 0.0;
};

bool has_line_break(std::string_view s) { return s.find_first_of("\r\n") != std::string_view::npos; }

void assert_writable(const RecordFile& file) {
  const auto check_entry = [](const HeaderEntry& e, bool truth) {
    INSMC_ASSERT(!e.key.empty() && e.key.find('=') == std::string::npos && !has_line_break(e.key) &&
                     trim(e.key) == e.key,
                 "header key '{}' cannot be written", e.key);
    INSMC_ASSERT(!has_line_break(e.value) && trim(e.value) == e.value, "header value '{}' of '{}' cannot be written",
                 e.value, e.key);
    INSMC_ASSERT(e.key.starts_with(kTruthKeyPrefix) == truth, "header key '{}' is in the wrong list", e.key);
    INSMC_ASSERT(!header_value_problem(e.key, e.value), "header {} = '{}': {}", e.key, e.value,
                 header_value_problem(e.key, e.value).value_or(""));
  };
  for (const auto& e : file.header.entries) check_entry(e, false);
  for (const auto& e : file.header.truth_entries) check_entry(e, true);
  for (std::string_view key : kRequiredHeaderKeys) {
    INSMC_ASSERT(file.header.find(key) != nullptr, "required header key '{}' missing", key);
  }
  const std::optional<HeaderProblem> consistency = header_consistency_problem(file.header);
  INSMC_ASSERT(!consistency, "header {}: {}", consistency ? consistency->key : "",
               consistency ? consistency->message : "");
  INSMC_ASSERT(!file.runs.empty(), "a record file needs at least one run");
  const double test_duration_s = file.header.test_duration_s();
  std::unordered_map<std::int64_t, int> ids;
  for (const RecordRun& run : file.runs) {
    INSMC_ASSERT(ids.emplace(run.id, 0).second, "run {} appears twice", run.id);
    RunChecker checker;
    for (const RecordRow& row : run.rows) {
      INSMC_ASSERT(row.run == run.id, "row of run {} in run {}", row.run, run.id);
      const auto problem = checker.check(row, test_duration_s);
      INSMC_ASSERT(!problem, "run {} at t_s = {}: {}", run.id, row.t_s, problem ? problem->message : "");
    }
    INSMC_ASSERT(checker.has_test_or_nav(), "run {} has no test or nav rows", run.id);
  }
}

void append_optional(fmt::memory_buffer& out, const std::optional<double>& v) {
  out.push_back(',');
  if (v) fmt::format_to(fmt::appender(out), "{}", *v);
}

}  // namespace

RecordFile parse_record_text(std::string_view text, std::string_view source_name) {
  return Parser(text_source(text), source_name).parse();
}

RecordFile read_record_file(const std::filesystem::path& path) {
  // Line by line: memory follows the rows kept, not the text.
  return Parser(capped_file_source(path, kMaxRecordFileBytes, "record file"), path.string()).parse();
}

std::string write_record_file(const RecordFile& file, TruthKeys truth) {
  assert_writable(file);
  fmt::memory_buffer out;
  const auto it = fmt::appender(out);
  fmt::format_to(it, "{}\n", kVersionLine);
  for (const auto& e : file.header.entries) fmt::format_to(it, "# {}={}\n", e.key, e.value);
  if (truth == TruthKeys::kKeep) {
    for (const auto& e : file.header.truth_entries) fmt::format_to(it, "# {}={}\n", e.key, e.value);
  }
  bool any_w = false;
  for (const RecordRun& run : file.runs) {
    for (const RecordRow& row : run.rows) any_w = any_w || row.has_w();
  }
  fmt::format_to(it, "{}{}\n", kRequiredColumnsText, any_w ? ",w_x,w_y,w_z" : "");
  for (const RecordRun& run : file.runs) {
    for (const RecordRow& row : run.rows) {
      fmt::format_to(it, "{},{},{}", row.run, row.t_s, to_string(row.phase));
      for (const auto& f : row.f_mps2) append_optional(out, f);
      if (row.r_ap_m) {
        fmt::format_to(it, ",{},{},{}", (*row.r_ap_m)[0], (*row.r_ap_m)[1], (*row.r_ap_m)[2]);
      } else {
        fmt::format_to(it, ",,,");
      }
      if (any_w) {
        for (const auto& w : row.w_radps) append_optional(out, w);
      }
      out.push_back('\n');
    }
  }
  return fmt::to_string(out);
}

}  // namespace insmc
