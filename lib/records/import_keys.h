#pragma once
/// The header keys `insmc import-imu` writes into a record file
/// (docs/real-data/import.md) and the diagnosis reads back (the null through
/// the import, the raw-sensor stage): one spelling for the writer and its
/// readers.
#include <string>
#include <string_view>

#include <fmt/format.h>

namespace insmc::import_keys {

// The recording and how it was read.
inline constexpr std::string_view kGyroUnit = "imu.gyro_unit";
inline constexpr std::string_view kAccelUnit = "imu.accel_unit";
inline constexpr std::string_view kGyroColumns = "imu.gyro_columns";
inline constexpr std::string_view kAccelColumns = "imu.accel_columns";
inline constexpr std::string_view kRateHz = "imu.rate_hz";
inline constexpr std::string_view kTimeColumn = "imu.time_column";
inline constexpr std::string_view kRunsFrom = "imu.runs_from";

// The strapdown navigation it went through.
inline constexpr std::string_view kAltitudeM = "imu.altitude_m";
inline constexpr std::string_view kAzimuthDeg = "imu.azimuth_deg";
inline constexpr std::string_view kAlignDurationS = "imu.align_duration_s";
inline constexpr std::string_view kNavDurationS = "imu.nav_duration_s";
inline constexpr std::string_view kGyroBias = "imu.gyro_bias";
inline constexpr std::string_view kSiteGravityMps2 = "imu.site_gravity_mps2";

/// The raw-sensor stage's status: "on", or why it was skipped.
inline constexpr std::string_view kNoise = "imu.noise";
/// Prefix of the raw-sensor stage's numeric keys (every key below kNoise).
inline constexpr std::string_view kNoisePrefix = "imu.noise.";
inline constexpr std::string_view kNoiseMaskedS = "imu.noise.masked_s";
inline constexpr std::string_view kNoiseSampleIntervalS = "imu.noise.sample_interval_s";

/// A raw-sensor stage value of one channel: imu.noise.<channel>.<what>
/// (e.g. imu.noise.gyro_x.equivalent_si).
inline std::string noise_key(std::string_view channel, std::string_view what) {
  return fmt::format("{}{}.{}", kNoisePrefix, channel, what);
}

/// A run's attitude at its alignment, which the null through the import turns its sensor by.
inline constexpr std::string_view kRunRollDeg = "roll_deg";
inline constexpr std::string_view kRunPitchDeg = "pitch_deg";

/// A value of one imported run: imu.run<id>.<what> (e.g. imu.run0.roll_deg).
inline std::string run_key(long long run_id, std::string_view what) {
  return fmt::format("imu.run{}.{}", run_id, what);
}

}  // namespace insmc::import_keys
