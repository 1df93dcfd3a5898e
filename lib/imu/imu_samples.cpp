#include "lib/common/enum_names.h"
#include "lib/imu/imu_samples.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <set>

#include "lib/common/input_text.h"
#include "lib/records/number_text.h"
#include "lib/units/quantity.h"
#include "lib/units/units.h"

namespace insmc {
namespace {

using records_detail::describe;
using records_detail::NumberStatus;
using records_detail::parse_double;

constexpr std::string_view kGyroAllowed = "must be one of: deg/s, rad/s, deg/h";
constexpr std::string_view kAccelAllowed = "must be one of: g, m/s2";



/// One field of a CSV line: its text without surrounding blanks and the
/// 1-based column of its first byte in the line.
struct Field {
  std::string_view text;
  std::size_t column;
};

void split_fields(std::string_view line, std::vector<Field>& out) {
  out.clear();
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = line.find(',', start);
    const std::size_t stop = comma == std::string_view::npos ? line.size() : comma;
    std::size_t first = start;
    while (first < stop && is_blank(line[first])) ++first;
    out.push_back(Field{trim(line.substr(start, stop - start)), first + 1});
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
}

/// What the reader needs of one wanted column: its header name and the
/// option that named it (for messages).
struct WantedColumn {
  std::string name;
  std::string option;
};

class Parser {
 public:
  /// Reads the lines of `bytes` as they come: memory holds one line (and
  /// the samples), never the file, so an endless stream (/dev/zero) stops at
  /// the line cap and a long one at its byte or sample cap.
  Parser(ByteSource bytes, std::string_view source, const ImuCsvOptions& o)
      : lines_(std::move(bytes), kMaxImuLineBytes), source_(echo_input(source, 256)), options_(o) {}

  ImuSamples parse() {
    std::string_view line;
    bool have_header = false;
    ImuSamples out;
    out.source = std::string(source_);
    std::vector<Field> fields;
    double first_time = 0.0, previous_time = 0.0;
    std::size_t previous_line = 0;
    const double gyro_si = to_si(options_.gyro_unit), accel_si = to_si(options_.accel_unit);
    const bool timed = !options_.time_column.empty();
    while (next_line(line)) {
      const std::string_view content = trim(line);
      if (content.empty() || content.front() == '#') continue;
      split_fields(line, fields);
      if (!have_header) {
        parse_header(fields);
        have_header = true;
        continue;
      }
      if (fields.size() != header_count_) {
        const std::size_t column = fields.size() > header_count_ ? fields[header_count_].column : line.size() + 1;
        fail(column, fmt::format("{} fields, but the header (line {}) has {}", fields.size(), header_line_,
                                 header_count_));
      }
      if (out.t_s.size() >= kMaxImuSamples)
        fail(1, fmt::format("more than {} samples: an IMU file may hold at most {} (11 h at 1 kHz); split it",
                            kMaxImuSamples, kMaxImuSamples));
      double values[7];
      for (std::size_t c = 0; c < wanted_.size(); ++c) {
        const Field& f = fields[index_[c]];
        const NumberStatus status = parse_double(f.text, values[c]);
        if (status != NumberStatus::kOk)
          fail(f.column, fmt::format("{} = '{}': {}", echo_input(wanted_[c].name), echo_input(f.text),
                                     describe(status)));
        if (c < 6) {
          const bool gyro = c < 3;
          const double si = (gyro ? gyro_si : accel_si) * values[c];
          const double cap = gyro ? kMaxImuGyroRadps : kMaxImuAccelMps2;
          const std::string_view unit = gyro ? to_string(options_.gyro_unit) : to_string(options_.accel_unit);
          if (!(std::abs(si) <= cap))
            fail(f.column, fmt::format("{} = '{}' {}: |{}| must be at most {:g} {} ({:g} {}); is the unit right?",
                                       echo_input(wanted_[c].name), echo_input(f.text), unit,
                                       gyro ? "gyro" : "accel", cap / (gyro ? gyro_si : accel_si), unit, cap,
                                       gyro ? "rad/s" : "m/s2"));
        }
      }
      double t = 0.0;
      if (timed) {
        t = values[6] * options_.time_unit_s;
        if (!(std::abs(t) <= kMaxImuAbsTimeS))
          fail(fields[index_[6]].column,
               fmt::format("{} = '{}': a time must lie within ±{} s", echo_input(wanted_[6].name),
                           echo_input(fields[index_[6]].text), kMaxImuAbsTimeS));
        if (out.t_s.empty()) first_time = t;
        t -= first_time;
        if (!out.t_s.empty() && !(t > previous_time)) {
          fail(fields[index_[6]].column,
               fmt::format("{} = '{}': time must increase strictly (line {} has {})", echo_input(wanted_[6].name),
                           echo_input(fields[index_[6]].text), previous_line, echo_input(previous_text_)));
        }
        previous_text_ = std::string(fields[index_[6]].text);
      } else {
        t = static_cast<double>(out.t_s.size()) / options_.rate_hz;
      }
      if (!(t <= kMaxImuDurationS))
        fail(timed ? fields[index_[6]].column : 1,
             fmt::format("sample at {} s after the first: an IMU file may cover at most {} s (14 days)", t,
                         kMaxImuDurationS));
      previous_time = t;
      previous_line = line_number_;
      out.t_s.push_back(t);
      out.gyro_b_radps.emplace_back(gyro_si * values[0], gyro_si * values[1], gyro_si * values[2]);
      out.accel_b_mps2.emplace_back(accel_si * values[3], accel_si * values[4], accel_si * values[5]);
    }
    if (!have_header)
      throw InputError(fmt::format("{}: no header line: the first line that is not blank or '#' must name the "
                                   "columns (e.g. {})",
                                   source_, echo_input(fmt::format("{}", fmt::join(column_names(), ",")), 200)));
    if (out.t_s.size() < 2)
      throw InputError(fmt::format("{}: {} data row(s) after the header (line {}): at least 2 samples are needed",
                                   source_, out.t_s.size(), header_line_));
    return out;
  }

 private:
  std::vector<std::string> column_names() const {
    std::vector<std::string> names;
    for (const WantedColumn& w : wanted()) names.push_back(w.name);
    return names;
  }

  std::vector<WantedColumn> wanted() const {
    std::vector<WantedColumn> w;
    for (const auto& n : options_.gyro_columns) w.push_back({n, "--gyro-columns"});
    for (const auto& n : options_.accel_columns) w.push_back({n, "--accel-columns"});
    if (!options_.time_column.empty()) w.push_back({options_.time_column, "--time-column"});
    return w;
  }

  void parse_header(const std::vector<Field>& fields) {
    header_line_ = line_number_;
    header_count_ = fields.size();
    wanted_ = wanted();
    index_.assign(wanted_.size(), 0);
    std::vector<std::string> missing;
    for (std::size_t c = 0; c < wanted_.size(); ++c) {
      std::optional<std::size_t> found;
      for (std::size_t i = 0; i < fields.size(); ++i) {
        if (fields[i].text != wanted_[c].name) continue;
        if (found)
          fail(fields[i].column, fmt::format("duplicate column '{}' (also column {} of the header)",
                                             echo_input(wanted_[c].name), fields[*found].column));
        found = i;
      }
      if (found)
        index_[c] = *found;
      else
        missing.push_back(fmt::format("'{}' ({})", echo_input(wanted_[c].name), wanted_[c].option));
    }
    if (!missing.empty()) {
      std::vector<std::string_view> have;
      for (const Field& f : fields) have.push_back(f.text);
      fail(1, fmt::format("missing column(s) {}: the header has {}; name the columns with --gyro-columns, "
                          "--accel-columns (x,y,z) and --time-column",
                          fmt::join(missing, ", "), echo_input(fmt::format("{}", fmt::join(have, ",")), 200)));
    }
  }

  bool next_line(std::string_view& line) {
    const bool got = lines_.next(line, [&](std::size_t length, bool measured_all) {
      ++line_number_;
      fail(kMaxImuLineBytes + 1, fmt::format("line of {}{} bytes: an IMU CSV line may hold at most {} bytes",
                                             measured_all ? "" : "more than ", length, kMaxImuLineBytes));
    });
    if (!got) return false;
    ++line_number_;
    if (line_number_ == 1 && line.starts_with("\xEF\xBB\xBF")) line.remove_prefix(3);  // UTF-8 byte-order mark
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    return true;
  }

  [[noreturn]] void fail(std::size_t column, const std::string& message) const {
    throw InputError(fmt::format("{}:{}:{}: {}", source_, line_number_, column, message));
  }

  LineReader lines_;
  std::string source_;  ///< the file name, escaped for messages
  const ImuCsvOptions& options_;
  std::size_t line_number_ = 0;
  std::size_t header_line_ = 0, header_count_ = 0;
  std::vector<WantedColumn> wanted_;
  std::vector<std::size_t> index_;  ///< header index of each wanted column
  std::string previous_text_;
};

}  // namespace

namespace {
constexpr EnumName<GyroUnit> kGyroUnitNames[] = {
    {GyroUnit::kDegPerS, "deg/s"}, {GyroUnit::kRadPerS, "rad/s"}, {GyroUnit::kDegPerH, "deg/h"}};
constexpr EnumName<AccelUnit> kAccelUnitNames[] = {{AccelUnit::kG, "g"}, {AccelUnit::kMps2, "m/s2"}};
}  // namespace

std::string_view to_string(GyroUnit u) { return name_of<GyroUnit>(kGyroUnitNames, u); }

std::string_view to_string(AccelUnit u) { return name_of<AccelUnit>(kAccelUnitNames, u); }

GyroUnit parse_gyro_unit(std::string_view text, std::string_view field) {
  if (const auto u = value_named<GyroUnit>(kGyroUnitNames, text)) return *u;
  throw InputError(std::string(field), echo_input(text), std::string(kGyroAllowed));
}

AccelUnit parse_accel_unit(std::string_view text, std::string_view field) {
  if (const auto u = value_named<AccelUnit>(kAccelUnitNames, text)) return *u;
  throw InputError(std::string(field), echo_input(text), std::string(kAccelAllowed));
}

double to_si(GyroUnit u) {
  switch (u) {
    case GyroUnit::kDegPerS: return kDegToRad;
    case GyroUnit::kRadPerS: return 1.0;
    case GyroUnit::kDegPerH: return kDegphToRadps;
  }
  return 1.0;
}

double to_si(AccelUnit u) { return u == AccelUnit::kG ? kGravityMps2 : 1.0; }

double parse_rate_hz(std::string_view text, std::string_view field) {
  const std::string s(text);
  constexpr std::string_view allowed = "a sample rate > 0 with the unit Hz or kHz (e.g. 100Hz)";
  // The number and the unit each read whole (lib/units/quantity.h).
  const std::optional<QuantityText> q = split_quantity(text);
  if (!q) throw InputError(std::string(field), echo_input(s), fmt::format("not a number; expected {}", allowed));
  const double number = q->number;
  const std::string_view unit = q->unit;
  double factor = 0.0;
  if (unit == "Hz") factor = 1.0;
  else if (unit == "kHz") factor = 1e3;
  else if (unit.empty()) throw InputError(std::string(field), echo_input(s), fmt::format("a unit is required; expected {}", allowed));
  else throw InputError(std::string(field), echo_input(s), fmt::format("unknown unit '{}'; expected {}", echo_input(unit), allowed));
  const double rate = number * factor;
  if (!std::isfinite(rate) || !(rate > 0))
    throw InputError(std::string(field), echo_input(s), fmt::format("must be finite and > 0; expected {}", allowed));
  if (!(rate >= kMinImuRateHz && rate <= kMaxImuRateHz))
    throw InputError(std::string(field), echo_input(s),
                     fmt::format("must lie in [{}Hz, {}kHz]", kMinImuRateHz, kMaxImuRateHz / 1e3));
  return rate;
}

void validate(const ImuCsvOptions& o) {
  const bool timed = !o.time_column.empty();
  if (!timed && !(o.rate_hz > 0 && std::isfinite(o.rate_hz)))
    throw InputError("--rate", fmt::format("{}Hz", o.rate_hz),
                     "give a finite sample rate > 0 (e.g. 100Hz), or a time column with --time-column");
  if (!timed && !(o.rate_hz >= kMinImuRateHz && o.rate_hz <= kMaxImuRateHz))
    throw InputError("--rate", fmt::format("{}Hz", o.rate_hz),
                      fmt::format("must lie in [{}Hz, {}kHz]", kMinImuRateHz, kMaxImuRateHz / 1e3));
  if (timed && o.rate_hz != 0.0)
    throw InputError("--rate", fmt::format("{}Hz", o.rate_hz),
                      "give either --rate or --time-column, not both");
  if (!(o.time_unit_s >= 1e-9 && o.time_unit_s <= 86400.0))
    throw InputError("--time-unit", fmt::format("{}s", o.time_unit_s), "must lie in [1ns, 1 day]");
  std::set<std::string> seen;
  const auto check = [&](const std::string& name, const char* option) {
    if (name.empty()) throw InputError(option, "''", "column names must not be empty");
    if (name.find(',') != std::string::npos || name.front() == '#')
      throw InputError(option, echo_input(name), "a column name cannot contain ',' or start with '#'");
    // The reader trims the header's fields and the name goes into the
    // record header: blanks at its ends or control bytes could never match.
    if (is_blank(name.front()) || is_blank(name.back()))
      throw InputError(option, "'" + echo_input(name) + "'", "a column name cannot start or end with a blank");
    for (const char ch : name)
      if (static_cast<unsigned char>(ch) < 0x20 || ch == 0x7F)
        throw InputError(option, echo_input(name), "a column name cannot contain control characters");
    if (!seen.insert(name).second) throw InputError(option, echo_input(name), "each column may be used once");
  };
  for (const auto& n : o.gyro_columns) check(n, "--gyro-columns");
  for (const auto& n : o.accel_columns) check(n, "--accel-columns");
  if (timed) check(o.time_column, "--time-column");
}

ImuSamples parse_imu_csv(std::string_view text, std::string_view source_name, const ImuCsvOptions& options) {
  validate(options);
  return Parser(text_source(text), source_name, options).parse();
}

std::optional<InputError> hole_problem(const ImuSamples& s) {
  if (s.size() < 3) return std::nullopt;
  std::vector<double> steps(s.size() - 1);
  for (std::size_t k = 0; k + 1 < s.size(); ++k) steps[k] = s.t_s[k + 1] - s.t_s[k];
  std::vector<double> sorted = steps;
  std::nth_element(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(sorted.size() / 2), sorted.end());
  const double median = sorted[sorted.size() / 2];
  for (std::size_t k = 0; k < steps.size(); ++k)
    if (steps[k] > kMaxImuHoleSpacings * median)
      return InputError(echo_input(s.source, 256), fmt::format("a step of {:g} s after t = {:g} s", steps[k], s.t_s[k]),
                        fmt::format("a hole in the recording: steps of more than {:g} times the median spacing "
                                    "({:g} s) are refused (import each stretch on its own)",
                                    kMaxImuHoleSpacings, median));
  return std::nullopt;
}

ImuSamples read_imu_csv(const std::filesystem::path& path, const ImuCsvOptions& options) {
  validate(options);
  // Read as parsed, a chunk at a time (the byte cap of read_file_capped);
  // the first chunk tells a gzip file by its magic bytes.
  ByteSource file = capped_file_source(path, kMaxImuFileBytes, "IMU file");
  ByteSource checked = [file = std::move(file), path, first = true](char* buffer, std::size_t size) mutable {
    const std::size_t got = file(buffer, size);
    if (first && got >= 2 && static_cast<unsigned char>(buffer[0]) == 0x1f &&
        static_cast<unsigned char>(buffer[1]) == 0x8b)
      throw InputError(fmt::format("{}: gzip-compressed; import-imu reads plain CSV: unpack it first "
                                   "(gzip -dc {} > FILE.csv) and give FILE.csv",
                                   echo_input(path.string(), 256), echo_input(path.string(), 256)));
    first = false;
    return got;
  };
  return Parser(std::move(checked), path.string(), options).parse();
}

}  // namespace insmc
