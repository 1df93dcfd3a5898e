#include "montecarlo/records/runs/files/layout.h"

#include <algorithm>
#include <cmath>
#include <utility>
#include <fmt/format.h>

#include "lib/common/assert.h"
#include "lib/common/input_error.h"
#include "lib/records/number_text.h"
#include "lib/units/units.h"

namespace insmc::runs {
namespace {

constexpr std::array<const char*, 3> kAxis = {"x", "y", "z"};
constexpr std::array<const char*, kNavWindows> kWindow = {"0-42 min", "42-63 min", "63-84 min",
                                                          "after 84 min"};

/// Rows kept at a spacing: a time is due when it lies a spacing or more
/// after the anchor, which then moves on by whole spacings. On a regular
/// grid whose step divides the spacing the anchor is the last time kept;
/// a record one run lacks delays that run's next row only, not every row
/// after it, so runs that each miss other records keep their rows in common
/// (layout_union.h).
struct Spaced {
  double anchor_s = -1e300;
  /// `tolerance`: the share of the spacing a time may fall short by.
  bool due(double t_s, double spacing_s, double tolerance) {
    if (anchor_s < -1e299) {
      anchor_s = t_s;
      return true;
    }
    if (t_s - anchor_s < spacing_s * (1 - tolerance)) return false;
    anchor_s += spacing_s * std::floor((t_s - anchor_s) / spacing_s + tolerance);
    return true;
  }
};

}  // namespace

int group_of(Stage stage, Quantity quantity, int axis, int window) {
  if (stage == Stage::kTest) return (quantity == Quantity::kF ? 0 : 3) + axis;
  if (quantity == Quantity::kF) return 6 + axis;
  return 9 + 3 * window + axis;
}

std::string group_name(int g) {
  if (g == kEstimatesGroup) return "estimates vs prior";
  const std::string axis = kAxis[static_cast<std::size_t>(group_axis(g))];
  if (g < 3) return "test f_" + axis;
  if (g < 6) return "test r_" + axis;
  if (g < 9) return "nav f_" + axis;
  return "nav r_" + axis + " " + group_window(g);
}

std::string group_stage(int g) {
  if (g == kEstimatesGroup) return "estimates vs prior";
  return g < 6 ? "test-run fit" : "post-test navigation";
}

int group_axis(int g) { return g == kEstimatesGroup ? -1 : g % 3; }

std::string group_window(int g) {
  if (g == kEstimatesGroup) return "";
  if (g < 6) return "test";
  if (g < 9) return "after test";
  return kWindow[static_cast<std::size_t>((g - 9) / 3)];
}

int nav_window(double t_s, double test_duration_s) {
  const double minutes = (t_s - test_duration_s) / 60.0;
  if (minutes <= 42.0) return 0;
  if (minutes <= 63.0) return 1;
  if (minutes <= 84.0) return 2;
  return 3;
}

NavSegment nav_segment_of(Scheme scheme) {
  return realigns(scheme) ? NavSegment::kRestart : resets_at_test_end(scheme) ? NavSegment::kReset : NavSegment::kContinue;
}

std::size_t rows_begun(const Layout& run, const Layout& longer) {
  if (run.test_rows != longer.test_rows || run.nav != longer.nav || run.nav_start_s != longer.nav_start_s ||
      run.rows.size() > longer.rows.size())
    return 0;
  const auto same_until = [&](std::size_t n) {
    return std::equal(run.rows.begin(), run.rows.begin() + static_cast<std::ptrdiff_t>(n), longer.rows.begin());
  };
  const std::size_t n = run.rows.size();
  if (same_until(n)) return n;
  // The run's last r row (three axes at one time, after its test rows).
  const bool last_is_r = n >= static_cast<std::size_t>(run.test_rows) + 3 &&
                         std::all_of(run.rows.end() - 3, run.rows.end(), [&](const ObservationRow& r) {
                           return r.quantity == Quantity::kR && r.t_s == run.rows.back().t_s;
                         });
  return last_is_r && same_until(n - 3) ? n - 3 : 0;
}

Layout Layout::test_part() const {
  Layout l;
  l.rows.assign(rows.begin(), rows.begin() + test_rows);
  l.test_rows = test_rows;
  return l;
}

Layout Layout::restarted_part() const {
  Layout l;
  for (std::size_t i = static_cast<std::size_t>(test_rows); i < rows.size(); ++i) {
    l.rows.push_back(rows[i]);
    l.rows.back().t_s = clock_s(i);
  }
  return l;
}

int coherent_group_of(int g) {
  if (g == kEstimatesGroup) return kCoherentCount - 1;
  return g < 9 ? g : 9 + g % 3;
}

std::string coherent_group_name(int c) {
  if (c == kCoherentCount - 1) return "common estimates";
  const std::string axis = kAxis[static_cast<std::size_t>(c % 3)];
  const char* what[] = {"test f_", "test r_", "nav f_", "nav r_"};
  return std::string("common ") + what[c / 3] + axis;
}

int coherent_representative(int c) { return c == kCoherentCount - 1 ? kEstimatesGroup : c; }

double median_f_spacing(const RecordFile& file) {
  // Consecutive f rows of the test runs: the navigation rows may be sampled
  // or averaged otherwise, and outnumber the test's.
  struct Step {
    double d_s;
    bool opens_run;
  };
  std::vector<Step> steps;
  for (const RecordRun& run : file.runs) {
    double last = -1.0;
    bool first = true;
    for (const RecordRow& row : run.rows) {
      if (row.phase != Phase::kTest || !row.has_f()) continue;
      if (last >= 0.0) steps.push_back({row.t_s - last, std::exchange(first, false)});
      last = row.t_s;
    }
  }
  if (steps.empty()) return 0.0;
  std::vector<double> spacings(steps.size());
  std::transform(steps.begin(), steps.end(), spacings.begin(), [](const Step& s) { return s.d_s; });
  std::nth_element(spacings.begin(), spacings.begin() + static_cast<std::ptrdiff_t>(spacings.size() / 2),
                   spacings.end());
  const double median = spacings[spacings.size() / 2];
  if (!(median > 0.0)) return 0.0;
  // Time stamps that jitter put the median one stamp's jitter off τ (a few
  // 1e-4 of it), and the windows counted from it drift off the records
  // within the test run. Each stretch of consecutive windows spans its
  // windows' τ less two stamps' jitter: the stretches' spans over their
  // windows give τ to that jitter over the windows counted.
  const auto windows_of = [&](const Step& s) {
    const double k = std::round(s.d_s / median);
    return k >= 1.0 && std::abs(s.d_s - k * median) <= kMaxStampJitter * 2.0 * median ? k : 0.0;
  };
  double span_s = 0.0, windows = 0.0;
  long pairs = 0, stretches = 0;
  bool in_stretch = false;
  for (const Step& s : steps) {
    const double k = windows_of(s);
    if (k > 0.0) {
      stretches += in_stretch && !s.opens_run ? 0 : 1;
      span_s += s.d_s;
      windows += k;
      ++pairs;
    }
    in_stretch = k > 0.0;
  }
  if (!(windows > 0.0)) return median;
  const double tau = span_s / windows;
  double squared_off = 0.0;
  for (const Step& s : steps)
    if (const double k = windows_of(s); k > 0.0) squared_off += (s.d_s - k * tau) * (s.d_s - k * tau);
  // A pair's difference is two stamps' jitter, var 2 s²; a stretch's span
  // is its ends' two, so var(span_s) = 2 s² per stretch.
  const double sigma_s = std::sqrt(static_cast<double>(stretches) * squared_off / static_cast<double>(pairs)) / windows;
  if (!(sigma_s > 1e-9 * tau)) return median;  // exact stamps: the spacing itself
  // A recorder's interval is set in few digits: the value of fewest digits
  // within three standard errors (10 s, not 9.9999 s, whose windows would not
  // divide the test run), down to the decade of the standard error.
  const double finest = std::pow(10.0, std::floor(std::log10(sigma_s)));
  for (double decade = std::pow(10.0, std::floor(std::log10(tau))); decade > finest * 0.5; decade /= 10.0) {
    const double rounded = std::round(tau / decade) * decade;
    if (rounded > 0.0 && std::abs(rounded - tau) <= 3.0 * sigma_s) return rounded;
  }
  return std::round(tau / finest) * finest;
}

RecordSite read_site(const RecordHeader& header, double default_pulse_mps) {
  RecordSite site;
  site.system = header.system();
  site.model.latitude_rad = header.latitude_deg() * kDegToRad;
  site.test_duration_s = header.test_duration_s();
  site.dv_pulse_mps = header.dv_pulse_mps().value_or(default_pulse_mps);
  site.position_resolution_m = header.position_resolution_m().value_or(0.0);
  site.scheme = header.scheme();
  if (realigns(site.scheme)) {
    const std::optional<double> start = header.nav_start_s();
    if (!start)
      throw InputError("header nav_start_s", "(missing)",
                       fmt::format("records after scheme {} need the time of the second switch-over after the "
                                   "realignment, > test_duration_s", to_string(site.scheme)));
    if (!(*start > site.test_duration_s))
      throw InputError("header nav_start_s", fmt::format("{}", *start),
                       fmt::format("must be > test_duration_s = {} (the realignment follows the test run)",
                                   site.test_duration_s));
    site.nav_start_s = *start;
  } else if (resets_at_test_end(site.scheme)) {
    site.nav_start_s = site.test_duration_s;
  }
  if (const std::string* tau = header.find("filter_interval_s")) {
    double v = 0.0;
    if (records_detail::parse_double(*tau, v) != records_detail::NumberStatus::kOk || !(v > 0))
      throw InputError("header filter_interval_s", *tau, "must be a number of seconds > 0");
    site.filter_interval_s = v;
  } else {
    site.filter_interval_s = 0.0;  // filled in from the data by the caller
  }
  if (const std::string* warmup = header.find(std::string(kKeyWarmupS))) {
    double v = 0.0;
    if (records_detail::parse_double(*warmup, v) != records_detail::NumberStatus::kOk || !(v >= 0) || v > 48 * 3600.0)
      throw InputError("header warmup_s", *warmup, "must be a number of seconds in [0, 172800] (switch-on to switch-over)");
    site.warmup_s = v;
    site.warmup_from_header = true;
  }
  if (site.system == System::kGyrocompass && std::abs(header.latitude_deg()) >= 89.0)
    throw InputError("header latitude_deg", fmt::format("{}", header.latitude_deg()),
                     "system 2 (gyrocompass) needs |latitude| < 89 deg");
  return site;
}

std::vector<RunData> extract_runs(const RecordFile& file, const RecordSite& site,
                                  const ExtractionOptions& options) {
  INSMC_ASSERT(site.filter_interval_s > 0, "filter interval {}", site.filter_interval_s);
  const double T = site.test_duration_s, tau = site.filter_interval_s;
  const NavSegment segment = nav_segment_of(site.scheme);
  // f rows the model does not describe: after 5.4 the torquers turn the
  // platform from switch-over, after a realignment the second navigation's
  // platform is torqued or newly aligned (r rows alone are modelled there).
  std::vector<RunData> runs;
  for (const RecordRun& record : file.runs) {
    RunData run;
    run.id = record.id;
    run.layout.nav = segment;
    run.layout.nav_start_s = site.nav_start_s;
    std::vector<ObservationRow> test_rows, nav_rows;
    std::vector<double> test_values, nav_values;
    std::array<double, 3> last_f = {-1e300, -1e300, -1e300};
    double last_r = -1e300;
    std::array<Spaced, 3> f_spaced;
    Spaced r_spaced;
    const RecordRow* last_r_row = nullptr;
    const auto window_of = [&](double t) {
      return segment == NavSegment::kRestart ? nav_window(t - site.nav_start_s + T, T) : nav_window(t, T);
    };
    for (const RecordRow& row : record.rows) {
      if (row.phase == Phase::kAlign) continue;
      run.end_s = row.t_s;
      const bool test = row.phase == Phase::kTest;
      if (!test && segment == NavSegment::kRestart && row.t_s <= site.nav_start_s)
        throw InputError(fmt::format("records run {} t_s", record.id), fmt::format("{}", row.t_s),
                         fmt::format("after scheme {} the nav rows are the navigation after the realignment: t_s > "
                                     "nav_start_s = {}", to_string(site.scheme), site.nav_start_s));
      auto& rows = test ? test_rows : nav_rows;
      auto& values = test ? test_values : nav_values;
      const Stage stage = test ? Stage::kTest : Stage::kNav;
      const int window = test ? 0 : window_of(row.t_s);
      // (f rows modelled are on the first navigation's clock, t_s.)
      const bool f_modelled = !uses_alignment_data(site.scheme) && (test || segment != NavSegment::kRestart);
      for (int k = 0; k < 3 && f_modelled; ++k) {
        // A window must lie after switch-over and not overlap the last one.
        const double spacing = test ? tau : std::max(tau, options.nav_f_spacing_s);
        if (!row.f_mps2[k] || row.t_s < tau * (1 - 1e-9) || row.t_s - last_f[k] < tau * (1 - 1e-6) ||
            !f_spaced[k].due(row.t_s, spacing, 1e-6))
          continue;
        last_f[k] = row.t_s;
        rows.push_back({row.t_s, Quantity::kF, k, group_of(stage, Quantity::kF, k, window)});
        values.push_back(*row.f_mps2[k]);
      }
      last_r_row = &row;
      const double r_spacing = test ? options.r_spacing_s : options.nav_r_spacing_s;
      if (!row.r_ap_m || !r_spaced.due(row.t_s, r_spacing, 1e-9)) continue;
      last_r = row.t_s;
      for (int k = 0; k < 3; ++k) {
        rows.push_back({row.t_s, Quantity::kR, k, group_of(stage, Quantity::kR, k, window)});
        values.push_back((*row.r_ap_m)[k]);
      }
    }
    // The last r row of a run always counts (it carries the longest time).
    if (last_r_row && last_r_row->r_ap_m && last_r_row->t_s > last_r) {
      const bool test = last_r_row->phase == Phase::kTest;
      const Stage stage = test ? Stage::kTest : Stage::kNav;
      const int window = test ? 0 : window_of(last_r_row->t_s);
      for (int k = 0; k < 3; ++k) {
        (test ? test_rows : nav_rows)
            .push_back({last_r_row->t_s, Quantity::kR, k, group_of(stage, Quantity::kR, k, window)});
        (test ? test_values : nav_values).push_back((*last_r_row->r_ap_m)[k]);
      }
    }
    run.layout.test_rows = static_cast<int>(test_rows.size());
    run.layout.rows = std::move(test_rows);
    run.layout.rows.insert(run.layout.rows.end(), nav_rows.begin(), nav_rows.end());
    run.values = std::move(test_values);
    run.values.insert(run.values.end(), nav_values.begin(), nav_values.end());
    runs.push_back(std::move(run));
  }
  return runs;
}

}  // namespace insmc::runs
