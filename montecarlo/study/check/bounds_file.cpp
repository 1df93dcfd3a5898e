#include "montecarlo/study/check/bounds_file.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <optional>

#include "lib/common/input_error.h"
#include "lib/units/physical_range.h"
#include "lib/common/input_text.h"
#include "lib/records/number_text.h"
#include "lib/units/quantity.h"
#include "lib/units/units.h"
#include "montecarlo/study/model/study_config.h"

namespace insmc::mc {
namespace {

constexpr std::string_view kKeys = "scheme, system, axis, t_min, confidence";
constexpr std::string_view kLimitForms =
    "METRIC_UNIT<=NUMBER or METRIC<=NUMBERUNIT (rms_m<=9000, cep50_nmi<=2, 2drms<=3nmi; METRIC rms, cep50, cep95 "
    "(or p95) or 2drms, UNIT m, ft or nmi, NUMBER >= 0)";
constexpr std::array<std::pair<std::string_view, BoundMetric>, 5> kMetrics = {{{"rms", BoundMetric::kRms},
                                                                              {"cep50", BoundMetric::kCep50},
                                                                              {"p95", BoundMetric::kCep95},
                                                                              {"cep95", BoundMetric::kCep95},
                                                                              {"2drms", BoundMetric::k2drms}}};
// The units a limit's key may carry (rms_ft): factor to metres.
constexpr std::array<std::pair<std::string_view, double>, 3> kKeyUnits = {
    {{"m", 1.0}, {"ft", kFtToM}, {"nmi", kNmiToM}}};
constexpr std::array<std::pair<std::string_view, Axis>, 4> kAxes = {
    {{"x", Axis::kX}, {"y", Axis::kY}, {"z", Axis::kZ}, {"horizontal", Axis::kHorizontal}}};

/// The metric a limit token starts with (rms_m<=…, cep50<=…), if any.
std::optional<std::pair<std::string_view, BoundMetric>> limit_metric(std::string_view text) {
  for (const auto& m : kMetrics)
    if (text.starts_with(m.first) && text.size() > m.first.size() &&
        (text[m.first.size()] == '_' || text[m.first.size()] == '<'))
      return m;
  return std::nullopt;
}

/// The bounds file's name of an axis (kAxes).
std::string_view axis_name(Axis a) {
  for (const auto& [name, axis] : kAxes)
    if (axis == a) return name;
  return "?";
}


/// One whitespace-separated token and its 1-based column.
struct Token {
  std::string_view text;
  std::size_t column;
};

class BoundsParser {
 public:
  BoundsParser(std::string_view text, std::string_view source) : text_(text), source_(echo_input(source, 256)) {}

  std::vector<Bound> parse() {
    if (text_.starts_with("\xEF\xBB\xBF")) text_.remove_prefix(3);  // UTF-8 byte-order mark
    std::vector<Bound> out;
    std::vector<double> times;
    std::size_t pos = 0;
    for (line_ = 1; pos < text_.size(); ++line_) {
      const std::size_t nl = text_.find('\n', pos);
      const std::size_t end = nl == std::string_view::npos ? text_.size() : nl;
      if (end - pos > kMaxBoundsLineBytes)
        fail(kMaxBoundsLineBytes + 1, fmt::format("line of {} bytes: a bounds line may hold at most {} bytes",
                                                  end - pos, kMaxBoundsLineBytes));
      std::string_view line = text_.substr(pos, end - pos);
      pos = end + 1;
      if (const std::size_t hash = line.find('#'); hash != std::string_view::npos) line = line.substr(0, hash);
      std::optional<Bound> b = parse_line(line);
      if (!b) continue;
      if (out.size() >= kMaxBounds)
        fail(1, fmt::format("more than {} bounds: a bounds file may hold at most {}", kMaxBounds, kMaxBounds));
      if (std::find(times.begin(), times.end(), b->t_s) == times.end()) {
        if (times.size() >= kMaxBoundsReportTimes)
          fail(time_column_, fmt::format("more than {} distinct t_min values: a bounds file may ask for at most {} "
                                         "report times",
                                         kMaxBoundsReportTimes, kMaxBoundsReportTimes));
        times.push_back(b->t_s);
      }
      out.push_back(*b);
    }
    if (out.empty()) throw InputError(fmt::format("{}: holds no bound (one a line: {})", source_, kExample));
    return out;
  }

 private:
  static constexpr std::string_view kExample = "scheme=none system=2 axis=horizontal t_min=84 rms_m<=9000";

  [[noreturn]] void fail(std::size_t column, const std::string& message) const {
    throw InputError(fmt::format("{}:{}:{}: {}", source_, line_, column, message));
  }

  std::optional<Bound> parse_line(std::string_view line) {
    std::vector<Token> tokens;
    for (std::size_t i = 0; i < line.size();) {
      while (i < line.size() && is_blank(line[i])) ++i;
      const std::size_t start = i;
      while (i < line.size() && !is_blank(line[i])) ++i;
      if (i > start) tokens.push_back({line.substr(start, i - start), start + 1});
    }
    if (tokens.empty()) return std::nullopt;  // blank or comment line
    std::map<std::string_view, Token> kv;
    std::optional<Token> limit;
    Bound b;
    b.line = static_cast<int>(line_);
    for (const Token& t : tokens) {
      if (limit_metric(t.text)) {
        if (limit)
          fail(t.column, fmt::format("a second limit {} (the first at column {}): one limit a line",
                                     quote(t.text), limit->column));
        parse_limit(t, b);
        limit = t;
        continue;
      }
      const std::size_t eq = t.text.find('=');
      if (eq == std::string_view::npos || eq == 0)
        fail(t.column, fmt::format("token {}: expected key=value ({}) or {}", quote(t.text), kKeys, kLimitForms));
      const std::string_view key = t.text.substr(0, eq);
      if (key != "scheme" && key != "system" && key != "axis" && key != "t_min" && key != "confidence")
        fail(t.column, fmt::format("unknown key {}; allowed: {}", quote(key), kKeys));
      const auto [it, inserted] = kv.emplace(key, Token{t.text.substr(eq + 1), t.column + eq + 1});
      if (!inserted)
        fail(t.column, fmt::format("{} given twice on one line (first at column {})", key, it->second.column - eq - 1));
    }
    for (std::string_view key : {"scheme", "system", "axis", "t_min"})
      if (!kv.count(key))
        fail(1, fmt::format("missing {}: each bound needs scheme, system, axis, t_min and a limit (rms_m<=N)", key));
    if (!limit) fail(1, fmt::format("missing the limit: each bound needs one, {}", kLimitForms));
    b.scheme = parse_scheme_token(kv.at("scheme"));
    b.system = parse_system_token(kv.at("system"));
    b.axis = parse_axis_token(kv.at("axis"));
    if (b.metric != BoundMetric::kRms && b.axis != Axis::kHorizontal)
      fail(limit->column, fmt::format("limit {}: {} is {} of the horizontal radial error; it needs "
                                      "axis=horizontal, not axis={}",
                                      quote(limit->text), names_of(b.metric).key,
                                      b.metric == BoundMetric::k2drms ? "twice the RMS" : "a percentile",
                                      axis_name(b.axis)));
    const Token& t_min = kv.at("t_min");
    const double minutes = number(t_min, "t_min");
    if (!(minutes >= 0 && minutes <= 360))
      fail(t_min.column, fmt::format("t_min = {}: must be a number of minutes in [0, 360]", quote(t_min.text)));
    b.t_s = minutes * 60.0;
    time_column_ = t_min.column;
    if (const auto c = kv.find("confidence"); c != kv.end()) {
      const double v = number(c->second, "confidence");
      // The range of --confidence (kConfidenceRange): above it the normal
      // quantile of the upper limit leaves double precision.
      if (!kConfidenceRange.contains(v))
        fail(c->second.column, fmt::format("confidence = {}: must lie in [{:g}, {:g}] (a one-sided upper confidence "
                                           "level, as --confidence)",
                                           quote(c->second.text), kConfidenceRange.min_si, kConfidenceRange.max_si));
      b.confidence = v;
    }
    return b;
  }

  /// METRIC_UNIT<=NUMBER or METRIC<=NUMBERUNIT, exactly: anything else that
  /// starts with a metric (rms_m>=5, rms_km<=5, rms_m=5) would otherwise
  /// read as no limit at all.
  void parse_limit(const Token& t, Bound& b) const {
    const auto [metric_name, metric] = *limit_metric(t.text);
    const std::size_t le = t.text.find("<=");
    if (le == std::string_view::npos) fail(t.column, fmt::format("limit {}: expected {}", quote(t.text), kLimitForms));
    const std::string_view key = t.text.substr(0, le);
    const Token value{t.text.substr(le + 2), t.column + le + 2};
    double x = 0;
    if (key == metric_name) {  // the unit with the number: cep50<=3nmi
      try {
        x = parse_quantity(value.text, Dimension::kLength, key);
      } catch (const InputError& e) {
        fail(value.column, e.what());
      }
      b.unit = value.text.ends_with("nmi") || value.text.ends_with("NM") ? LengthUnit::kNauticalMile
               : value.text.ends_with("ft")                              ? LengthUnit::kFoot
                                                                         : LengthUnit::kMetre;
    } else {
      const std::string_view unit = key.substr(metric_name.size() + 1);
      const auto u = std::find_if(kKeyUnits.begin(), kKeyUnits.end(), [&](const auto& k) { return k.first == unit; });
      if (u == kKeyUnits.end()) fail(t.column, fmt::format("limit {}: expected {}", quote(t.text), kLimitForms));
      x = number(value, key) * u->second;
      b.unit = unit == "nmi" ? LengthUnit::kNauticalMile : unit == "ft" ? LengthUnit::kFoot : LengthUnit::kMetre;
    }
    if (!(x >= 0) || !(x <= kPositionLimitRange.max_si))
      fail(value.column, fmt::format("{}: the limit must lie in [0, 40000 km] (the earth's circumference)", quote(t.text)));
    b.metric = metric;
    b.limit_m = x;
  }

  double number(const Token& t, std::string_view what) const {
    double v = 0.0;
    const auto status = records_detail::parse_double(t.text, v);
    if (status != records_detail::NumberStatus::kOk)
      fail(t.column, fmt::format("{} = {}: {}", what, quote(t.text), records_detail::describe(status)));
    return v;
  }

  Scheme parse_scheme_token(const Token& t) const {
    std::string names;
    for (Scheme s : all_schemes()) {
      if (to_string(s) == t.text) return s;
      names += (names.empty() ? "" : ", ") + std::string(to_string(s));
    }
    fail(t.column, fmt::format("scheme = {}: must be one of: {}", quote(t.text), names));
  }

  System parse_system_token(const Token& t) const {
    if (t.text == "1") return System::kTheodolite;
    if (t.text == "2") return System::kGyrocompass;
    fail(t.column, fmt::format("system = {}: must be 1 (theodolite) or 2 (gyrocompassing)", quote(t.text)));
  }

  Axis parse_axis_token(const Token& t) const {
    for (const auto& [name, axis] : kAxes)
      if (name == t.text) return axis;
    fail(t.column, fmt::format("axis = {}: must be x, y, z or horizontal", quote(t.text)));
  }

  static std::string quote(std::string_view text) { return fmt::format("'{}'", echo_input(text)); }

  std::string_view text_;
  std::string source_;
  std::size_t line_ = 0;
  std::size_t time_column_ = 1;
};

}  // namespace

BoundMetricNames names_of(BoundMetric m) {
  if (m == BoundMetric::kCep50) return {"cep50", "CEP50"};
  if (m == BoundMetric::kCep95) return {"p95", "CEP95"};
  if (m == BoundMetric::k2drms) return {"2drms", "2DRMS"};
  return {"rms", "RMS"};
}

std::vector<Bound> parse_bounds_text(std::string_view text, std::string_view source) {
  return BoundsParser(text, source).parse();
}

std::vector<Bound> read_bounds_file(const std::string& path) {
  return parse_bounds_text(read_file_capped(path, kMaxBoundsFileBytes, "bounds file"), path);
}

}  // namespace insmc::mc
