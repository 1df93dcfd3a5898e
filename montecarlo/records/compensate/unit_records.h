#pragma once
/// Records in, for one unit on the flight line: the test run of each run of
/// a record file (docs/records.md), as `insmc compensate` uses it. The site
/// is completed as the gap diagnosis completes it (values the header leaves
/// out are inferred from the rows and said); f windows shorter than the
/// report's filter box are summed into longer ones; the report's estimators
/// (4.4), (4.8), (5.10) are applied to each run's own test rows.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "lib/preflight/test_run.h"
#include "lib/preflight/test_run_estimates.h"
#include "lib/records/record.h"
#include "montecarlo/records/runs/files/site_values.h"
#include "montecarlo/records/runs/files/layout.h"

namespace insmc::compensate {

/// One unit's test run: f and r at t_k = kτ, k = 1..K, per axis (the data
/// the estimators use), and what the estimators made of them. A run whose
/// logger dropped records has the intervals it has.
struct UnitTestRun {
  std::int64_t id = 0;
  runs::Layout layout;       ///< the test rows only (f then r per t_k, axes x, y, z)
  Eigen::VectorXd values;   ///< in layout order [m/s², m]
  TestRunEstimators estimators;  ///< the fits (4.4), (4.8) over the intervals of `layout`
  TestRunEstimates estimates;
};

/// The rows of a test run of K filter intervals τ: at each t_k = kτ the f
/// rows of x, y, z, then the r rows.
runs::Layout test_run_layout(int K, double tau_s);

/// The site's estimators over the intervals a test-run layout has (f and r
/// each with all three axes at t_k); the site's own where it has them all.
TestRunEstimators layout_estimators(const runs::RecordSite& site, const runs::Layout& layout);

struct UnitRecords {
  runs::RecordSite site;  ///< completed; its estimators set
  std::vector<runs::SiteValue> site_values;
  std::vector<std::string> statements;  ///< what was inferred or changed, and why
  std::vector<UnitTestRun> runs;
};

/// Longest filter box and fewest intervals compensate takes the records'
/// test run to (the estimators' data and the conditioning's rows grow with
/// K = T/τ; K ≤ 120 keeps one unit's model below 800 rows).
inline constexpr double kUnitFilterIntervalS = 10.0;
inline constexpr int kMaxUnitIntervals = 120;

/// `run`: the one run to take (its id in the file), or every run.
/// `site_gravity_mps2`: the specific force at the site, which the model's
/// accelerometer and tilt terms are scaled by (default the report's g; a
/// site's differs by up to 0.3 %, which the most precise estimates resolve).
/// A run may lack some intervals' f or r (the fits take the rest, and a
/// statement says how many); throws InputError naming the file's field when
/// a run holds less than half of the fits' intervals (where shorter f
/// windows are summed into them: fewer than 6 of them or less than half of
/// its recorded f windows or r rows, counted at the recorder's spacing), or
/// the site cannot be completed.
UnitRecords read_unit_records(const RecordFile& file, const UncertaintyModel& prior,
                              std::optional<std::int64_t> run = std::nullopt,
                              std::optional<double> site_gravity_mps2 = std::nullopt);

}  // namespace insmc::compensate
