#pragma once
/// Records of real or simulated runs in memory: the content of a record file
/// of format v1 (docs/records.md). One run = one alignment,
/// its test run and its navigation on a stationary base. Reading and writing
/// the CSV text is in lib/records/record_io.h.
#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "lib/records/import_keys.h"
#include "lib/common/optional_value.h"
#include "lib/common/system.h"
#include "lib/compensation/scheme.h"

namespace insmc {

/// Stage of a run a record row belongs to. Within a run the phases come in
/// this order: align (t_s < 0), test (0 ≤ t_s ≤ T), nav (t_s > T).
enum class Phase { kAlign, kTest, kNav };

/// "align", "test", "nav": the one spelling used in record files.
std::string_view to_string(Phase p);
/// Parses one phase name; throws InputError naming `field` otherwise.
Phase parse_phase(std::string_view text, std::string_view field = "phase");

/// One `# key=value` header line (key and value without surrounding blanks).
struct HeaderEntry {
  std::string key;
  std::string value;
  bool operator==(const HeaderEntry&) const = default;
};

/// The header keys of record format v1 and the prefix of the simulator's keys.
inline constexpr std::string_view kKeyLatitudeDeg = "latitude_deg";
inline constexpr std::string_view kKeySystem = "system";
inline constexpr std::string_view kKeyTestDurationS = "test_duration_s";
inline constexpr std::string_view kKeyScheme = "scheme";
inline constexpr std::string_view kKeyDvPulseMps = "dv_pulse_mps";
inline constexpr std::string_view kKeyPositionResolutionM = "position_resolution_m";
inline constexpr std::string_view kKeyNavStartS = "nav_start_s";
inline constexpr std::string_view kKeyFilterIntervalS = "filter_interval_s";
/// Optional: switch-on to switch-over [s] (a thermal transient's warm-up).
inline constexpr std::string_view kKeyWarmupS = "warmup_s";
/// Prefix of the raw-sensor stage's numeric keys (import-imu; "imu.noise" alone is its status).
inline constexpr std::string_view kRawStagePrefix = import_keys::kNoisePrefix;
inline constexpr std::string_view kTruthKeyPrefix = "truth.";

/// Required keys, in the order the writer's factory puts them.
inline constexpr std::array<std::string_view, 4> kRequiredHeaderKeys = {
    kKeyLatitudeDeg, kKeySystem, kKeyTestDurationS, kKeyScheme};

/// Physical ranges of the header values, checked by the reader (with the
/// range in the message) and asserted by the writer. Generous: far beyond
/// any real preflight test, tight enough that no value can make a consumer
/// loop for ever or overflow (a pulse weight of 1e-300 m/s would make the
/// truth simulator count pulses for ever).
/// A run (alignment, test run and navigation) lasts at most 48 h: the
/// report's flights last 84 min, a long test campaign a working day; every
/// row's |t_s| and every duration in the header is capped by it.
inline constexpr double kMaxRunDurationS = 48 * 3600.0;
/// Accelerometer pulse weight: 0 (continuous) or [1 µm/s, 10 m/s]; the
/// report's is 0.1 ft/s = 0.03 m/s, navigation-grade ones 1e-4..1e-2 m/s.
inline constexpr double kMinDvPulseMps = 1e-6;
inline constexpr double kMaxDvPulseMps = 10.0;
/// Position-computer resolution: 0 (exact) or [1 µm, 10 km]; the report's is 3 ft.
inline constexpr double kMinPositionResolutionM = 1e-6;
inline constexpr double kMaxPositionResolutionM = 1e4;
/// Filter (output) interval: [0.1 ms, 1 h]; 0.1 ms is a 10 kHz IMU's sample.
inline constexpr double kMinFilterIntervalS = 1e-4;
inline constexpr double kMaxFilterIntervalS = 3600.0;
/// Test run of a scheme that estimates from it (5.1.x, combined, 5.2, 5.3):
/// what the study's test run allows (preflight/test_run.h validate): at most
/// 2 h, a whole number of filter intervals, at least 4 of them.
inline constexpr double kMaxEstimatingTestDurationS = 2 * 3600.0;
/// A test row stamped after T by at most this share of its spacing from the
/// test row before is the row at T (a recorder's time-stamp jitter,
/// docs/records.md); compensate and gap take rows within 1 % of τ of the grid.
inline constexpr double kTestEndJitter = 0.01;
/// A recorder's time stamps may jitter by up to this share of τ about the
/// windows' grid (docs/records.md): the readers of records place rows on
/// their grid within it.
inline constexpr double kMaxStampJitter = 0.01;
inline constexpr int kMinTestIntervals = 4;

/// Checks the value of a known header key (required or optional); returns
/// what is allowed when `value` is impossible (e.g. "must be in [-90, 90]"),
/// std::nullopt when it is fine or the key is not one of the known keys.
std::optional<std::string> header_value_problem(std::string_view key, std::string_view value);

struct RecordHeader;

/// A problem between header values (each alone in range): the key to blame
/// and what is wrong. E.g. nav_start_s missing or not after test_duration_s
/// for a scheme that realigns; filter_interval_s longer than the test run.
struct HeaderProblem {
  std::string key;
  std::string message;
};
/// Checks the header's values together; std::nullopt when consistent.
/// Precondition: every known key present passes header_value_problem.
std::optional<HeaderProblem> header_consistency_problem(const RecordHeader& header);

/// The header of a record file: key/value pairs kept in the order given.
/// Keys beginning `truth.` belong to the simulator that wrote the file; they
/// are kept apart in `truth_entries` and the diagnosis never reads them
/// (use `without_truth()` before handing a header to it). Unknown keys are
/// kept in `entries` and ignored by the typed accessors.
///
/// The typed accessors parse the stored text each time; on a header that
/// came from read_record_file they cannot fail. On a header built in code
/// they throw InputError ("key = value: allowed") for a missing required key
/// or an impossible value.
struct RecordHeader {
  std::vector<HeaderEntry> entries;        ///< non-truth keys, in file order
  std::vector<HeaderEntry> truth_entries;  ///< `truth.*` keys, in file order

  /// A header with the four required keys (numbers in shortest round-trip form).
  static RecordHeader make(double latitude_deg, System system, double test_duration_s, Scheme scheme);

  /// The value of `key` (searched in `entries`, or in `truth_entries` for a
  /// `truth.` key), or nullptr.
  const std::string* find(std::string_view key) const;
  /// Replaces the value of `key` or appends it (to `truth_entries` for a
  /// `truth.` key).
  void set(std::string_view key, std::string value);
  /// As above, the number written as fmt "{}" (shortest exact round trip).
  void set(std::string_view key, double value);

  double latitude_deg() const;     ///< required, in [-90, 90] (deg)
  System system() const;           ///< required, 1 or 2
  double test_duration_s() const;  ///< required, T > 0 (s)
  Scheme scheme() const;           ///< required: none, 5.1.1, 5.1.2, combined, 5.2, 5.3, 5.4
  /// Pulse weight of `f` (m/s), ≥ 0; 0 means a continuous output.
  std::optional<double> dv_pulse_mps() const;
  /// Resolution of `r` (m), ≥ 0.
  std::optional<double> position_resolution_m() const;
  /// Time of the second switch-over after a realignment (s, ≥ 0, same time
  /// origin as t_s).
  std::optional<double> nav_start_s() const;
  /// The filter interval of `f` (s).
  std::optional<double> filter_interval_s() const;

  /// A copy without the `truth.` keys: all the diagnosis may see.
  RecordHeader without_truth() const;

  bool operator==(const RecordHeader&) const = default;
};

/// One CSV row. Empty fields hold nothing (lib/common/optional_value.h:
/// a row takes 104 bytes, so that millions of them fit).
struct RecordRow {
  std::int64_t run = 0;       ///< run number (any integer; equals the owning RecordRun::id)
  double t_s = 0.0;           ///< time since the switch to navigation mode (s)
  Phase phase = Phase::kTest;
  /// Filtered accelerometer output error Δf^a_k (m/s²) over the interval
  /// ending at t_s, k = x, y, z; each component may be missing on its own.
  std::array<OptionalValue, 3> f_mps2{};
  /// Position error r_k (computed − true, m) in the ideal instrument frame a'
  /// (x north, y east, z down at t = 0). Present on every test and nav row;
  /// may be missing on align rows.
  OptionalVector3 r_ap_m;
  /// Gyro torquer command rates w_k (rad/s), recorded during alignment
  /// (phase align; accepted on any row); each component may be missing.
  std::array<OptionalValue, 3> w_radps{};

  bool has_f() const { return f_mps2[0] || f_mps2[1] || f_mps2[2]; }
  bool has_w() const { return w_radps[0] || w_radps[1] || w_radps[2]; }
  bool operator==(const RecordRow&) const = default;
};

/// The rows of one run in time order (phases align, then test, then nav).
struct RecordRun {
  std::int64_t id = 0;
  std::vector<RecordRow> rows;
  bool operator==(const RecordRun&) const = default;
};

/// A whole record file: header and runs, in order of first appearance.
struct RecordFile {
  RecordHeader header;
  std::vector<RecordRun> runs;
  bool operator==(const RecordFile&) const = default;
};

/// A copy of `file` with the `truth.` header keys removed.
RecordFile without_truth(RecordFile file);

}  // namespace insmc
