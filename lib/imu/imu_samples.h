#pragma once
/// Raw IMU samples from a CSV file: three gyro and three accelerometer
/// columns in the sensor (body) frame b, in units the user declares, sampled
/// at a declared rate or stamped by a time column. The first step of the
/// path from real data to records (`insmc import-imu`, docs/real-data/import.md).
///
/// Sample convention: sample k holds the gyro rate ω_ib^b and the specific
/// force f^b over [t_k, t_{k+1}) (a zero-order hold from its time stamp; the
/// last sample lasts as long as the one before it). Inside, everything is SI.
///
/// The reader is strict: a missing or duplicate column, a wrong field count,
/// a non-numeric or non-finite value, or a time that does not increase is an
/// InputError whose one-line message starts `FILE:LINE:COLUMN: ` (1-based)
/// and names the column. Plain CSV only: a gzip file is refused with the
/// command that unpacks it.
#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "lib/common/input_error.h"
#include "lib/frames/frames.h"

namespace insmc {

/// Caps of the reader, far beyond any real recording so that a user never
/// meets them, and stated so that a broken or hostile file is refused before
/// it fills the memory (each sample costs ~60 bytes in memory, more in the
/// strapdown run that follows).
/// Samples in one file: 40 million (11 h at 1 kHz; 2.4 GB in memory).
inline constexpr std::size_t kMaxImuSamples = 40'000'000;
/// The file: 4 GiB (40 million rows of ~100 bytes).
inline constexpr std::uint64_t kMaxImuFileBytes = std::uint64_t{4} << 30;
/// One line: 64 KiB (loggers write tens of columns; the wanted ones are 7).
inline constexpr std::size_t kMaxImuLineBytes = 64 * 1024;
/// Sample rate: [1 Hz, 100 kHz] (navigation IMUs log at 100 Hz to 2 kHz).
inline constexpr double kMinImuRateHz = 1.0;
inline constexpr double kMaxImuRateHz = 1e5;
/// Time covered by one file: 14 days (a file holds consecutive runs of at
/// most 48 h each); a time-column value, times its unit, lies within
/// ±1e10 s (Unix time in seconds is 1.8e9 s).
inline constexpr double kMaxImuDurationS = 14 * 86400.0;
inline constexpr double kMaxImuAbsTimeS = 1e10;
/// Per component: |gyro| ≤ 100 rad/s (5730 deg/s: MEMS full scales reach
/// 4000 deg/s), |accel| ≤ 10,000 m/s² (1000 g: full scales reach 400 g).
/// A value beyond is a unit or column mistake, or corrupt data.
inline constexpr double kMaxImuGyroRadps = 100.0;
inline constexpr double kMaxImuAccelMps2 = 1e4;

/// Units of the gyro columns.
enum class GyroUnit { kDegPerS, kRadPerS, kDegPerH };
/// Units of the accelerometer columns (g = 9.80665 m/s², units.h).
enum class AccelUnit { kG, kMps2 };

/// "deg/s", "rad/s", "deg/h": the spelling on the command line and in headers.
std::string_view to_string(GyroUnit u);
/// "g", "m/s2".
std::string_view to_string(AccelUnit u);
/// Parse one unit name; throw InputError naming `field` and the allowed names.
GyroUnit parse_gyro_unit(std::string_view text, std::string_view field);
AccelUnit parse_accel_unit(std::string_view text, std::string_view field);
/// SI factor of a unit: rad/s per column unit, m/s² per column unit.
double to_si(GyroUnit u);
double to_si(AccelUnit u);

/// A sample rate with its unit, "100Hz" or "0.1kHz" [Hz]; throws InputError
/// naming `field` on a missing unit, a malformed number or a rate outside
/// [kMinImuRateHz, kMaxImuRateHz].
double parse_rate_hz(std::string_view text, std::string_view field);

/// How to read an IMU CSV file.
struct ImuCsvOptions {
  /// Gyro columns for the sensor x, y, z axes (header names, exact match).
  std::array<std::string, 3> gyro_columns = {"gyro_x_dps", "gyro_y_dps", "gyro_z_dps"};
  /// Accelerometer columns for the sensor x, y, z axes.
  std::array<std::string, 3> accel_columns = {"acc_x_g", "acc_y_g", "acc_z_g"};
  GyroUnit gyro_unit = GyroUnit::kDegPerS;
  AccelUnit accel_unit = AccelUnit::kG;
  /// Sample rate [Hz], > 0 and finite, used when `time_column` is empty:
  /// sample k (0-based) is at t = k / rate.
  double rate_hz = 0.0;
  /// Time column (seconds × `time_unit_s`); empty: use `rate_hz`. Times
  /// must increase strictly.
  std::string time_column;
  /// Seconds per unit of the time column, > 0 (1 for seconds).
  double time_unit_s = 1.0;
};

/// Checks every constraint on the options (one source of time, distinct
/// non-empty column names, rate within its caps, positive time unit);
/// throws InputError otherwise.
void validate(const ImuCsvOptions& options);

/// The samples of one file, SI, times relative to the first sample.
struct ImuSamples {
  std::string source;                ///< file name as given (for messages and headers)
  std::vector<double> t_s;           ///< sample times, t_s[0] = 0, strictly increasing [s]
  std::vector<Vec3> gyro_b_radps;    ///< ω_ib^b as measured [rad/s]
  std::vector<Vec3> accel_b_mps2;    ///< f^b as measured [m/s²]

  std::size_t size() const { return t_s.size(); }
  /// End of the interval of sample k: t_{k+1}, or for the last sample
  /// t_k + (t_k − t_{k−1}) [s]. Precondition: size() ≥ 2.
  double end_s(std::size_t k) const {
    return k + 1 < t_s.size() ? t_s[k + 1] : 2.0 * t_s[k] - t_s[k - 1];
  }
  /// The time the samples cover, from t_s[0] to the end of the last interval [s].
  double covered_s() const { return end_s(t_s.size() - 1); }
};

/// Parses CSV text: optional UTF-8 byte-order mark, blank lines and `#`
/// comment lines anywhere, then a header line naming the columns (any order,
/// extra columns ignored), then one row per sample. CRLF line endings and
/// blanks around fields are accepted. At least two samples are required; the
/// caps above hold (sample count, line length, duration, each value's
/// magnitude, with file:line:column and the cap in the message).
/// `source_name` stands for the file name in messages.
ImuSamples parse_imu_csv(std::string_view text, std::string_view source_name, const ImuCsvOptions& options);

/// Reads the file and parses it as parse_imu_csv does, a chunk at a time as
/// it parses: memory holds one line and the samples, never the file, so an
/// endless stream stops at a cap (/dev/zero at the line cap, within 1 MiB
/// past it). A gzip file (magic bytes 1f 8b) is refused with the command
/// that unpacks it.
ImuSamples read_imu_csv(const std::filesystem::path& path, const ImuCsvOptions& options);

/// A step between samples longer than this many times the file's median
/// spacing is a hole in the recording, not a logger's jitter or a dropped
/// sample or few: the strapdown would bridge it by holding one sample.
inline constexpr double kMaxImuHoleSpacings = 10.0;

/// The first hole of `samples` (InputError naming the file, the time and
/// the step against the median spacing), or nullopt.
std::optional<InputError> hole_problem(const ImuSamples& samples);

}  // namespace insmc
