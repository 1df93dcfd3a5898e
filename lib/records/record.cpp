#include "lib/common/enum_names.h"
#include "lib/records/record.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "lib/common/input_error.h"
#include "lib/records/number_text.h"

namespace insmc {
namespace {

using records_detail::NumberStatus;
using records_detail::parse_double;

bool is_truth_key(std::string_view key) { return key.starts_with(kTruthKeyPrefix); }

std::string scheme_names() {
  std::string names;
  for (Scheme s : all_schemes()) {
    names = names.empty() ? std::string(to_string(s)) : fmt::format("{}, {}", names, to_string(s));
  }
  return names;
}

/// Parses a numeric header value already known to be valid, or throws.
double header_number(const RecordHeader& h, std::string_view key) {
  const std::string* text = h.find(key);
  if (text == nullptr) throw InputError(std::string(key), "(missing)", "required header key");
  if (auto problem = header_value_problem(key, *text)) throw InputError(std::string(key), *text, *problem);
  double v = 0.0;
  parse_double(*text, v);
  return v;
}

std::optional<double> optional_header_number(const RecordHeader& h, std::string_view key) {
  if (h.find(key) == nullptr) return std::nullopt;
  return header_number(h, key);
}

}  // namespace

constexpr EnumName<Phase> kPhaseNames[] = {{Phase::kAlign, "align"}, {Phase::kTest, "test"}, {Phase::kNav, "nav"}};

std::string_view to_string(Phase p) { return name_of<Phase>(kPhaseNames, p); }

Phase parse_phase(std::string_view text, std::string_view field) {
  if (const auto p = value_named<Phase>(kPhaseNames, text)) return *p;
  throw InputError(std::string(field), std::string(text), "must be one of: align, test, nav");
}

std::optional<std::string> header_value_problem(std::string_view key, std::string_view value) {
  const bool known = key == kKeyLatitudeDeg || key == kKeySystem || key == kKeyTestDurationS ||
                     key == kKeyDvPulseMps || key == kKeyPositionResolutionM || key == kKeyNavStartS ||
                     key == kKeyFilterIntervalS;
  if (key == kKeyScheme) {
    for (Scheme s : all_schemes()) {
      if (to_string(s) == value) return std::nullopt;
    }
    return fmt::format("must be one of: {}", scheme_names());
  }
  // The raw-sensor stage's results (import-imu, docs/noise.md): every
  // imu.noise.* key below "imu.noise" itself is a number the null of
  // imported records synthesizes noise from, so a corrupt one must not pass
  // as an absent term.
  const bool raw_stage = key.starts_with(kRawStagePrefix);
  if (!known && !raw_stage) return std::nullopt;
  double v = 0.0;
  const NumberStatus status = parse_double(value, v);
  if (status != NumberStatus::kOk) return fmt::format("must be a finite number ({})", describe(status));
  if (raw_stage && key.ends_with(".warm_up_excluded") && v != 0.0 && v != 1.0)
    return "must be 0 or 1 (whether the raw stage left out the first, non-stationary part)";
  if (raw_stage && !(v >= 0.0)) return "must be a non-negative number (SI; a fitted noise term, its interval or time)";
  const double max_h = kMaxRunDurationS / 3600.0;
  if (key == kKeyLatitudeDeg && !(v >= -90.0 && v <= 90.0)) return "must be in [-90, 90] (degrees)";
  if (key == kKeySystem && v != 1.0 && v != 2.0) return "must be 1 (theodolite azimuth) or 2 (gyrocompassing)";
  if (key == kKeyTestDurationS && !(v > 0.0 && v <= kMaxRunDurationS))
    return fmt::format("must be in (0, {}] (seconds: a run lasts at most {} h)", kMaxRunDurationS, max_h);
  if (key == kKeyDvPulseMps && !(v == 0.0 || (v >= kMinDvPulseMps && v <= kMaxDvPulseMps)))
    return fmt::format("must be 0 (a continuous output) or in [{}, {}] (m/s)", kMinDvPulseMps, kMaxDvPulseMps);
  if (key == kKeyPositionResolutionM &&
      !(v == 0.0 || (v >= kMinPositionResolutionM && v <= kMaxPositionResolutionM)))
    return fmt::format("must be 0 (exact) or in [{}, {}] (m)", kMinPositionResolutionM, kMaxPositionResolutionM);
  if (key == kKeyNavStartS && !(v >= 0.0 && v <= kMaxRunDurationS))
    return fmt::format("must be in [0, {}] (seconds since the first switch-over: a run lasts at most {} h)",
                       kMaxRunDurationS, max_h);
  if (key == kKeyFilterIntervalS && !(v >= kMinFilterIntervalS && v <= kMaxFilterIntervalS))
    return fmt::format("must be in [{}, {}] (seconds)", kMinFilterIntervalS, kMaxFilterIntervalS);
  return std::nullopt;
}

std::optional<HeaderProblem> header_consistency_problem(const RecordHeader& h) {
  for (std::string_view key : kRequiredHeaderKeys)
    if (h.find(key) == nullptr) return HeaderProblem{std::string(key), "required header key is missing"};
  const double T = h.test_duration_s();
  const Scheme scheme = h.scheme();
  const std::optional<double> nav_start = h.nav_start_s(), tau = h.filter_interval_s();
  if (realigns(scheme) && !nav_start)
    return HeaderProblem{std::string(kKeyNavStartS),
                         fmt::format("missing: records after scheme {} need the time of the second switch-over "
                                     "after the realignment (> test_duration_s = {})",
                                     to_string(scheme), T)};
  if (realigns(scheme) && !(*nav_start > T))
    return HeaderProblem{std::string(kKeyNavStartS),
                         fmt::format("nav_start_s = {}: must be > test_duration_s = {} (the realignment follows "
                                     "the test run)",
                                     *nav_start, T)};
  if (tau && !(*tau <= T))
    return HeaderProblem{std::string(kKeyFilterIntervalS),
                         fmt::format("filter_interval_s = {}: must be no longer than test_duration_s = {}", *tau, T)};
  if (uses_test_run(scheme)) {
    if (T > kMaxEstimatingTestDurationS)
      return HeaderProblem{std::string(kKeyTestDurationS),
                           fmt::format("test_duration_s = {}: must be at most {} s (2 h) for scheme {}, which "
                                       "estimates from the test run",
                                       T, kMaxEstimatingTestDurationS, to_string(scheme))};
    if (tau) {
      const double k = T / *tau;
      if (std::abs(k - std::round(k)) > 1e-6 || k < kMinTestIntervals - 1e-6)
        return HeaderProblem{std::string(kKeyFilterIntervalS),
                             fmt::format("filter_interval_s = {}: test_duration_s = {} must be a whole number (at "
                                         "least {}) of filter intervals for scheme {}, which estimates from the "
                                         "test run",
                                         *tau, T, kMinTestIntervals, to_string(scheme))};
    }
  }
  return std::nullopt;
}

RecordHeader RecordHeader::make(double latitude_deg, System system, double test_duration_s, Scheme scheme) {
  RecordHeader h;
  h.set(kKeyLatitudeDeg, latitude_deg);
  h.set(kKeySystem, fmt::format("{}", system_number(system)));
  h.set(kKeyTestDurationS, test_duration_s);
  h.set(kKeyScheme, std::string(to_string(scheme)));
  return h;
}

const std::string* RecordHeader::find(std::string_view key) const {
  const auto& list = is_truth_key(key) ? truth_entries : entries;
  const auto it = std::find_if(list.begin(), list.end(), [&](const HeaderEntry& e) { return e.key == key; });
  return it == list.end() ? nullptr : &it->value;
}

void RecordHeader::set(std::string_view key, std::string value) {
  auto& list = is_truth_key(key) ? truth_entries : entries;
  const auto it = std::find_if(list.begin(), list.end(), [&](const HeaderEntry& e) { return e.key == key; });
  if (it != list.end()) {
    it->value = std::move(value);
  } else {
    list.push_back(HeaderEntry{std::string(key), std::move(value)});
  }
}

void RecordHeader::set(std::string_view key, double value) { set(key, fmt::format("{}", value)); }

double RecordHeader::latitude_deg() const { return header_number(*this, kKeyLatitudeDeg); }

System RecordHeader::system() const {
  return header_number(*this, kKeySystem) == 1.0 ? System::kTheodolite : System::kGyrocompass;
}

double RecordHeader::test_duration_s() const { return header_number(*this, kKeyTestDurationS); }

Scheme RecordHeader::scheme() const {
  const std::string* text = find(kKeyScheme);
  if (text == nullptr) throw InputError(std::string(kKeyScheme), "(missing)", "required header key");
  for (Scheme s : all_schemes()) {
    if (to_string(s) == *text) return s;
  }
  throw InputError(std::string(kKeyScheme), *text, fmt::format("must be one of: {}", scheme_names()));
}

std::optional<double> RecordHeader::dv_pulse_mps() const { return optional_header_number(*this, kKeyDvPulseMps); }

std::optional<double> RecordHeader::position_resolution_m() const {
  return optional_header_number(*this, kKeyPositionResolutionM);
}

std::optional<double> RecordHeader::nav_start_s() const { return optional_header_number(*this, kKeyNavStartS); }

std::optional<double> RecordHeader::filter_interval_s() const {
  return optional_header_number(*this, kKeyFilterIntervalS);
}

RecordHeader RecordHeader::without_truth() const {
  RecordHeader copy;
  copy.entries = entries;
  return copy;
}

RecordFile without_truth(RecordFile file) {
  file.header.truth_entries.clear();
  return file;
}

}  // namespace insmc
