#include "montecarlo/records/compensate/unit_records.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

#include "lib/common/assert.h"
#include "lib/common/input_error.h"
#include "lib/records/record.h"
#include "montecarlo/records/runs/model/scheme_rows.h"
#include "montecarlo/records/runs/prepared_runs.h"

namespace insmc::compensate {
namespace {

/// A recorder's time stamps may jitter: a row within kMaxStampJitter of τ
/// (1 %) of t_k is t_k's (its window shifted by that much changes Δf by a
/// hundredth of a window's drift, and r by the velocity error over τ/100).
constexpr double kGridJitter = kMaxStampJitter;

/// The test row of `run` nearest t within kGridJitter τ, or nullptr.
const RecordRow* test_row_at(const RecordRun& run, double t_s, double tau_s) {
  const RecordRow* nearest = nullptr;
  for (const RecordRow& row : run.rows)
    if (row.phase == Phase::kTest && std::abs(row.t_s - t_s) <= kGridJitter * tau_s &&
        (nearest == nullptr || std::abs(row.t_s - t_s) < std::abs(nearest->t_s - t_s)))
      nearest = &row;
  return nearest;
}

/// The finer of the f and r spacings (0 when neither is recorded).
double finer_spacing(double f_spacing_s, double r_spacing_s) {
  if (!(f_spacing_s > 0)) return r_spacing_s;
  if (!(r_spacing_s > 0)) return f_spacing_s;
  return std::min(f_spacing_s, r_spacing_s);
}

/// A recorder that reads the phase from the time stamp labels the row at T
/// nav when it comes stamped a little after T. Where nothing reset the
/// navigation at T, that row is the test run's last: relabelled test when
/// the run has no test row within `jitter_s` of T.
void take_the_row_at_test_end(RecordRun& run, double test_duration_s, double jitter_s) {
  RecordRow* nav = nullptr;
  for (RecordRow& row : run.rows) {
    const double off_s = std::abs(row.t_s - test_duration_s);
    if (off_s > jitter_s) continue;
    if (row.phase == Phase::kTest) return;
    if (row.phase == Phase::kNav && (nav == nullptr || off_s < std::abs(nav->t_s - test_duration_s))) nav = &row;
  }
  if (nav != nullptr) nav->phase = Phase::kTest;
}

/// Whether a test row carries the quantity: r, or f on all three axes.
bool carries(const RecordRow& row, bool f) {
  return f ? row.f_mps2[0] && row.f_mps2[1] && row.f_mps2[2] : row.r_ap_m.has_value();
}

/// The median spacing of consecutive test rows carrying f (or r) over the
/// runs (0 when none): the recorder's f window or r interval, whatever the
/// header says.
double median_test_spacing(const RecordFile& file, bool f) {
  std::vector<double> spacings;
  for (const RecordRun& run : file.runs) {
    double last = -1.0;
    for (const RecordRow& row : run.rows) {
      if (row.phase != Phase::kTest || !carries(row, f)) continue;
      if (last >= 0 && row.t_s > last) spacings.push_back(row.t_s - last);
      last = row.t_s;
    }
  }
  if (spacings.empty()) return 0.0;
  std::nth_element(spacings.begin(), spacings.begin() + static_cast<std::ptrdiff_t>(spacings.size() / 2), spacings.end());
  return spacings[spacings.size() / 2];
}

/// The share of the test run a run's records cover, f and r apart, counted
/// at the recorder's own spacing: the rows it has over those the spacing
/// puts in (0, T]. Summing short windows into the fits' boxes drops every
/// box with one window missing, so a logger's 10 % of dropped 1-s records
/// leaves a third of the 10-s boxes: the run is still the test run the fits
/// were designed for, which the share of boxes would not say.
struct RecordedCover {
  double f = 0.0, r = 0.0;
};
RecordedCover recorded_cover(const RecordRun& run, double test_duration_s, double f_spacing_s, double r_spacing_s) {
  RecordedCover cover;
  for (const bool f : {true, false}) {
    const double spacing = f ? f_spacing_s : r_spacing_s;
    if (!(spacing > 0)) continue;
    const double slots = std::max(1.0, std::round(test_duration_s / spacing));
    long rows = 0;
    for (const RecordRow& row : run.rows)
      if (row.phase == Phase::kTest && row.t_s > 0 && row.t_s <= test_duration_s + kGridJitter * spacing &&
          carries(row, f))
        ++rows;
    (f ? cover.f : cover.r) = std::min(1.0, static_cast<double>(rows) / slots);
  }
  return cover;
}

/// What a run must hold to be fitted: half of the fits' K intervals, or,
/// where short windows are summed into the fits' boxes, half of its
/// recorded f windows and r rows over the test run (a logger's dropouts are
/// a few per cent; a run with more missing is not the test run the report's
/// fits were designed for); in either case at least as many intervals as a
/// short run's every one (6), the fits' four terms and their spread.
constexpr double kLeastRecordedCover = 0.5;
int fewest_intervals(int K) { return std::min(K, 6); }
int half_of_intervals(int K) { return std::max((K + 1) / 2, fewest_intervals(K)); }

UnitTestRun unit_test_run(const RecordRun& run, const RecordRun& recorded, const runs::RecordSite& site,
                          double f_spacing_s, double r_spacing_s, std::vector<std::string>& statements) {
  const double tau = site.filter_interval_s;
  const int K = runs::record_test_options(site).intervals();
  UnitTestRun out;
  out.id = run.id;
  out.layout.nav = runs::NavSegment::kContinue;
  Eigen::MatrixXd position = Eigen::MatrixXd::Zero(K, 3), accel = Eigen::MatrixXd::Zero(K, 3);
  std::vector<double> values;
  int with_f = 0, with_r = 0;
  double first_missing_s = -1;
  for (int k = 1; k <= K; ++k) {
    const double t = k * tau;
    const RecordRow* row = test_row_at(run, t, tau);
    const bool has_f = row != nullptr && row->f_mps2[0] && row->f_mps2[1] && row->f_mps2[2];
    const bool has_r = row != nullptr && row->r_ap_m.has_value();
    if ((!has_f || !has_r) && first_missing_s < 0) first_missing_s = t;
    // test_run_layout's order: at each t_k the f rows of x, y, z, then the r rows.
    for (const runs::Quantity q : {runs::Quantity::kF, runs::Quantity::kR}) {
      const bool is_f = q == runs::Quantity::kF;
      if (is_f ? !has_f : !has_r) continue;
      for (int a = 0; a < 3; ++a) {
        const double v = is_f ? *row->f_mps2[a] : (*row->r_ap_m)[a];
        (is_f ? accel : position)(k - 1, a) = v;
        out.layout.rows.push_back({t, q, a, runs::group_of(runs::Stage::kTest, q, a, 0)});
        values.push_back(v);
      }
    }
    with_f += has_f ? 1 : 0;
    with_r += has_r ? 1 : 0;
  }
  out.layout.test_rows = static_cast<int>(out.layout.rows.size());
  out.values = Eigen::Map<const Eigen::VectorXd>(values.data(), static_cast<Eigen::Index>(values.size()));
  const RecordedCover cover = recorded_cover(recorded, site.test_duration_s, f_spacing_s, r_spacing_s);
  const bool summed = f_spacing_s > 0 && f_spacing_s < tau * (1 - 2 * kGridJitter);
  // Every window recorded yet boxes lost: the time stamps stray from the
  // recorder's grid by more than summing allows (runs/files/filter_windows.h).
  const bool off_grid = summed && with_f < K && cover.f > 0.999;
  const int least = std::min(with_f, with_r);
  const bool holds = least >= half_of_intervals(K) ||
                     (summed && least >= fewest_intervals(K) && std::min(cover.f, cover.r) >= kLeastRecordedCover);
  const std::string counts =
      fmt::format("f at {} and r at {} of the {} filter intervals of the test run", with_f, with_r, K);
  const std::string first_missing =
      first_missing_s < 0 ? std::string("none missing") : fmt::format("the first missing at t = {:g} s", first_missing_s);
  // Shares rounded down: a run refused for 49.6 % does not read "50 %".
  const std::string shares = fmt::format("{:g} % of the recorded f windows and {:g} % of the r rows there",
                                         std::floor(1000 * cover.f) / 10, std::floor(1000 * cover.r) / 10);
  const std::string boxes =
      summed ? fmt::format("; {:g} s boxes summed from {:g} s windows, a box with a window missing left out; {}{}", tau,
                           f_spacing_s, shares,
                           off_grid ? fmt::format(" (every window is recorded: boxes were broken by time stamps more "
                                                  "than 1 % of {:g} s off the recorder's grid)",
                                                  f_spacing_s)
                                    : "")
             : "";
  if (!holds)
    throw InputError(fmt::format("records run {} test rows", run.id),
                     fmt::format("({}; {}{})", counts, first_missing, summed ? boxes : "; " + shares),
                     fmt::format("compensate fits (4.4), (4.8) over the intervals t_k = k*{:g} s (within {:g} s) up "
                                 "to T = {:g} s that have f and r (all three axes): a run must hold at least {} of the "
                                 "{} intervals, or, where shorter f windows are summed into them, at least {} of them "
                                 "and {:g} % of its recorded f windows and r rows",
                                 tau, kGridJitter * tau, site.test_duration_s, half_of_intervals(K), K,
                                 fewest_intervals(K), 100 * kLeastRecordedCover));
  if (with_f < K || with_r < K)
    statements.push_back(fmt::format("run {}: {} ({}{}): the fits (4.4), (4.8) are taken over the intervals it has",
                                     run.id, counts, first_missing, boxes));
  out.estimators = layout_estimators(site, out.layout);
  // The estimators as the Monte Carlo applies them (test_run.h); r rather
  // than Δr = r − r(0): records have no row at t = 0, so each estimate
  // carries the estimator's response to r(0) (scheme_rows.h models it).
  // A missing interval's data are zero here and its columns zero.
  const Eigen::Matrix<double, kEstimateRows, 3> e =
      apply_estimators<3>(out.estimators, site.model, site.test_duration_s, position, accel);
  out.estimates.u2 = e.row(kU2Row).transpose();
  out.estimates.u3 = e.row(kU3Row).transpose();
  out.estimates.u3_accel = e.row(kU3AccelRow).transpose();
  out.estimates.df_at_test_end_mps2 = e.row(kDfAtTestEndRow).transpose();
  return out;
}

}  // namespace

TestRunEstimators layout_estimators(const runs::RecordSite& site, const runs::Layout& layout) {
  INSMC_ASSERT(site.estimators.has_value(), "layout_estimators before the site's estimators");
  const double tau = site.filter_interval_s;
  const auto K = static_cast<std::size_t>(runs::record_test_options(site).intervals());
  std::vector<int> f_axes(K, 0), r_axes(K, 0);
  for (const runs::ObservationRow& row : layout.rows) {
    const long k = std::lround(row.t_s / tau);
    INSMC_ASSERT(k >= 1 && static_cast<std::size_t>(k) <= K, "test row at {} s off the filter grid", row.t_s);
    ++(row.quantity == runs::Quantity::kF ? f_axes : r_axes)[static_cast<std::size_t>(k - 1)];
  }
  ObservedIntervals observed;
  for (std::size_t k = 0; k < K; ++k) {
    observed.accel.push_back(f_axes[k] == 3);
    observed.position.push_back(r_axes[k] == 3);
  }
  const auto all = [](const std::vector<bool>& v) { return std::all_of(v.begin(), v.end(), [](bool b) { return b; }); };
  if (all(observed.accel) && all(observed.position)) return *site.estimators;
  // The site's choice of terms (resolvability, --fit-u4) stays: only the
  // intervals change.
  return make_estimators(runs::record_test_options(site), site.model, site.estimators->fit_u3,
                         site.estimators->fit_u4, observed);
}

runs::Layout test_run_layout(int K, double tau_s) {
  runs::Layout layout;
  layout.nav = runs::NavSegment::kContinue;
  for (int k = 1; k <= K; ++k)
    for (const runs::Quantity q : {runs::Quantity::kF, runs::Quantity::kR})
      for (int a = 0; a < 3; ++a) layout.rows.push_back({k * tau_s, q, a, runs::group_of(runs::Stage::kTest, q, a, 0)});
  layout.test_rows = static_cast<int>(layout.rows.size());
  return layout;
}

UnitRecords read_unit_records(const RecordFile& file, const UncertaintyModel& prior, std::optional<std::int64_t> run,
                              std::optional<double> site_gravity_mps2) {
  // Only the test run is read: what followed it in the records (a scheme,
  // a realignment) is not this unit's future.
  RecordFile tests = without_truth(file);
  // The recorder's spacings, and below the site's values the header leaves
  // out, from every run of the file: a run is judged and modelled the same
  // whether it is read alone (--run) or with the others.
  const double f_spacing_s = median_test_spacing(tests, true), r_spacing_s = median_test_spacing(tests, false);
  if (run && std::none_of(tests.runs.begin(), tests.runs.end(), [&](const RecordRun& r) { return r.id == *run; }))
    throw InputError("--run", std::to_string(*run),
                     fmt::format("must be the id of a run in the records (they hold {} runs, ids {} to {})",
                                 tests.runs.size(), tests.runs.empty() ? 0 : tests.runs.front().id,
                                 tests.runs.empty() ? 0 : tests.runs.back().id));
  // Under a scheme that acts from the switch-over (5.4) the test rows are
  // compensated already: not the data the estimators and this model take.
  const Scheme recorded = tests.header.scheme();
  if (uses_alignment_data(recorded))
    throw InputError("records' header scheme", std::string(to_string(recorded)),
                     "the test rows of these records were flown under that scheme's compensation (it acts from the "
                     "switch-over); give records of the uncompensated test run (scheme none or a scheme that uses "
                     "the test run)");
  const double T = tests.header.test_duration_s();
  if (runs::nav_segment_of(recorded) == runs::NavSegment::kContinue)
    // Within the jitter of the finer spacing, so that the row also lies on
    // the grid f windows are summed on (filter_windows.h).
    for (RecordRun& r : tests.runs) take_the_row_at_test_end(r, T, kGridJitter * finer_spacing(f_spacing_s, r_spacing_s));
  for (RecordRun& r : tests.runs) std::erase_if(r.rows, [](const RecordRow& row) { return row.phase != Phase::kTest; });
  tests.header.set(std::string(kKeyScheme), std::string(to_string(Scheme::kNone)));
  runs::RecordReading options;
  options.prior = prior;
  // The estimators fit r at the ends of the filter windows: windows at least
  // as long as the r spacing (less two rows' jitter) put an r row at each end.
  options.min_filter_interval_s =
      std::max({kUnitFilterIntervalS, T / kMaxUnitIntervals, r_spacing_s * (1 - 2 * kGridJitter)});
  UnitRecords out;
  runs::Records records = runs::read_records(tests, options, out.statements, out.site_values);
  if (run) {
    const auto other = [&](const RecordRun& r) { return r.id != *run; };
    std::erase_if(records.file.runs, other);
    std::erase_if(tests.runs, other);
  }
  out.site = records.site;
  if (site_gravity_mps2) out.site.model.gravity_mps2 = *site_gravity_mps2;
  if (out.site.test_duration_s / out.site.filter_interval_s > kMaxUnitIntervals + 1e-9)
    throw InputError("records' header filter_interval_s", fmt::format("{:g}", out.site.filter_interval_s),
                     fmt::format("compensate sums f windows up to at least T/{} = {:g} s; the recorded windows could "
                                 "not be summed so (gaps in the f rows)", kMaxUnitIntervals, T / kMaxUnitIntervals));
  out.site.estimators = record_estimators(out.site, prior);
  const int K = runs::record_test_options(out.site).intervals();
  if (std::abs(K * out.site.filter_interval_s - out.site.test_duration_s) > 1e-6 * out.site.test_duration_s)
    out.statements.push_back(fmt::format(
        "the filter interval {:g} s does not divide T = {:g} s: the fits (4.4), (4.8) take the {} windows that end "
        "within the test run (to {:g} s), and (5.10) carries them to T",
        out.site.filter_interval_s, out.site.test_duration_s, K, K * out.site.filter_interval_s));
  INSMC_ASSERT(records.file.runs.size() == tests.runs.size(), "runs read {} of {}", records.file.runs.size(),
               tests.runs.size());
  for (std::size_t i = 0; i < tests.runs.size(); ++i) {
    INSMC_ASSERT(records.file.runs[i].id == tests.runs[i].id, "run {} read as run {}", tests.runs[i].id,
                 records.file.runs[i].id);
    out.runs.push_back(unit_test_run(records.file.runs[i], tests.runs[i], out.site, f_spacing_s, r_spacing_s,
                                     out.statements));
  }
  return out;
}

}  // namespace insmc::compensate
