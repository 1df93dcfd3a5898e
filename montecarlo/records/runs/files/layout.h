#pragma once
/// What the gap diagnosis (docs/gap-method.md) takes from a record file (docs/records.md):
/// per run, the observations it compares with the model, in the order the
/// model's rows are built (test rows first: they are what the fit sees), and
/// the groups by which the gap is reported (axis × stage × time window).
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "lib/common/model_options.h"
#include "lib/common/system.h"
#include "lib/preflight/test_run.h"
#include "lib/records/record.h"

namespace insmc::runs {

enum class Quantity { kF, kR };  ///< filtered accelerometer error Δf, position error r
enum class Stage { kTest, kNav };

/// Report groups. Per axis k = x, y, z: the test-run fit residuals of f and
/// r, the post-test innovations of f, of r in the windows 0–42, 42–63,
/// 63–84 and > 84 min after the test, and the estimates against the prior.
inline constexpr int kNavWindows = 4;
inline constexpr int kGroupCount = 3 + 3 + 3 + 3 * kNavWindows + 1;
inline constexpr int kEstimatesGroup = kGroupCount - 1;
int group_of(Stage stage, Quantity quantity, int axis, int window);
std::string group_name(int group);      ///< e.g. "nav r_y 42-63 min"
std::string group_stage(int group);     ///< "test fit", "post-test navigation", "estimates vs prior"
int group_axis(int group);              ///< 0..2, or −1 for the estimates
std::string group_window(int group);    ///< "test", "0-42 min", ..., "" for the estimates
/// Window of a navigation time: minutes after the end of the test run T.
int nav_window(double t_s, double test_duration_s);

/// Coherent groups: what every run shares (a design or site effect, the same
/// signature in each run), per axis for the test-run f and r, the
/// post-test f and r (all windows), and the estimates.
inline constexpr int kCoherentCount = 13;
int coherent_group_of(int group);
std::string coherent_group_name(int coherent);  ///< e.g. "common nav r_y"
/// A report group inside a coherent group (for its stage and axis).
int coherent_representative(int coherent);

/// One observed value: a component of f or r at a time.
struct ObservationRow {
  double t_s = 0.0;
  Quantity quantity = Quantity::kR;
  int axis = 0;
  int group = 0;
  bool operator==(const ObservationRow&) const = default;
};

/// How a record's navigation rows follow its test run (the header's scheme,
/// docs/records.md).
enum class NavSegment {
  kContinue,  ///< none, 5.4: one navigation from switch-over
  kReset,     ///< 5.2, 5.3: position and velocity reset at T; instruments, platform and counters go on
  kRestart,   ///< 5.1.1, 5.1.2, combined: realigned and switched over again at nav_start_s
};
NavSegment nav_segment_of(Scheme scheme);

/// The rows of a run in model order: test rows, then navigation rows.
struct Layout {
  std::vector<ObservationRow> rows;
  int test_rows = 0;
  NavSegment nav = NavSegment::kContinue;
  double nav_start_s = 0.0;  ///< T after a reset, the second switch-over after a restart
  bool operator==(const Layout&) const = default;

  /// Row i belongs to the navigation after a realignment (its own clock).
  bool restarted(std::size_t i) const { return nav == NavSegment::kRestart && static_cast<int>(i) >= test_rows; }
  /// Time of row i on the clock of its navigation.
  double clock_s(std::size_t i) const { return restarted(i) ? rows[i].t_s - nav_start_s : rows[i].t_s; }
  /// The same layout with only the test rows, or only the navigation rows
  /// on their own clock (a restarted navigation as a layout of its own).
  Layout test_part() const;
  Layout restarted_part() const;
};

/// How many of `run`'s rows begin `longer` (the same test rows, then its
/// navigation rows in order): all of them, or all but the last r row (its
/// three axes), which extract_runs always keeps and a longer run need not
/// have at that time; 0 when `run` is not the beginning of `longer`.
std::size_t rows_begun(const Layout& run, const Layout& longer);

/// What the header says about the runs (non-`truth.` keys only).
struct RecordSite {
  System system = System::kTheodolite;
  ModelOptions model;                 ///< latitude from the header, the rest defaults
  double test_duration_s = 900.0;
  double filter_interval_s = 10.0;    ///< τ of f (header filter_interval_s, else the f spacing)
  double dv_pulse_mps = 0.0;          ///< 0: continuous f
  double position_resolution_m = 0.0;
  Scheme scheme = Scheme::kNone;      ///< applied after the test run
  double nav_start_s = 0.0;           ///< second switch-over (realigning schemes)
  /// Time from switch-on to switch-over (header warmup_s, else the
  /// thermal_transient effect's 900 s): the records see a transient only
  /// from switch-over on; its switch-on size is read through this.
  double warmup_s = 900.0;
  bool warmup_from_header = false;
  /// The scheme's least-squares estimators (set by the diagnosis for a
  /// scheme that uses the test run, scheme_rows.h).
  std::optional<TestRunEstimators> estimators;
};

/// One run: its layout and observed values (same order).
struct RunData {
  std::int64_t id = 0;
  Layout layout;
  std::vector<double> values;
  double end_s = 0.0;  ///< last time of the run
};

struct ExtractionOptions {
  /// One r row per slot of this (extract_runs): r is smooth, and the
  /// model's cost grows with the rows [s].
  double r_spacing_s = 30.0;
  /// The same for the navigation r rows: 72 per Schuler period still
  /// resolve what is smooth on that scale [s].
  double nav_r_spacing_s = 60.0;
  /// One navigation f row per slot of this (the test-run f rows are all
  /// kept at spacings ≥ τ: the fit uses them) [s].
  double nav_f_spacing_s = 30.0;
};

/// Reads the site from the header. `default_pulse_mps` applies when the
/// header has no dv_pulse_mps.
RecordSite read_site(const RecordHeader& header, double default_pulse_mps);

/// The runs' observations: f where the record has it at spacings ≥ τ (overlapping windows correlate), f after the
/// test and r one per slot of their spacing counted from the first kept (a record one run lacks moves one row, not
/// every row after it; on a grid whose step divides the spacing, every spacing). Runs are returned in file order.
std::vector<RunData> extract_runs(const RecordFile& file, const RecordSite& site,
                                  const ExtractionOptions& options = {});

/// The f spacing of a record when the header does not give τ, from the
/// consecutive f rows of the test runs: their median spacing where the time
/// stamps are exact; where they jitter (up to kMaxStampJitter of τ), the
/// stretches' spans over their windows, in the fewest digits within three
/// standard errors of it (0 when there are no f rows).
double median_f_spacing(const RecordFile& file);

}  // namespace insmc::runs
