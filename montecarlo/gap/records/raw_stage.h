#pragma once
/// What the raw-sensor stage found, when the records came through
/// `import-imu` with its noise stage (header keys imu.noise.*,
/// docs/noise.md): each channel's fitted noise as a constant error over one
/// Schuler period against Table 3.1. The diagnosis reports it beside its
/// own ranking and says when the two point at different sensors: in
/// navigation residuals a gyro drift (a tilt growing as g·∫ω) and an
/// accelerometer bias look alike, the raw outputs tell them apart.
#include <optional>
#include <string>
#include <vector>

#include "lib/records/record.h"

namespace insmc::mc {

struct RawChannel {
  std::string channel;        ///< gyro_x ... accel_z
  double equivalent_si = 0;   ///< rad/s or m/s²
  double ratio_to_bound = 0;  ///< against Table 3.1 (docs/noise.md §4)
  bool warm_up_excluded = false;
};

struct RawStage {
  std::vector<RawChannel> channels;
  double gyro_ratio = 0, accel_ratio = 0;  ///< the largest of each sensor
};

/// From the header; nullopt when the file holds no raw-stage keys.
std::optional<RawStage> raw_stage_from_header(const RecordHeader& header);

/// "gyro", "accelerometer" or "" for an effect (or class "a|b") the
/// diagnosis ranked.
std::string sensor_of_effect(const std::string& effect);

/// The statements for the report: the raw stage's verdict and, when the
/// navigation-level top candidate is of the other sensor than the one the
/// raw stage puts furthest outside Table 3.1, that they disagree.
std::vector<std::string> raw_stage_statements(const RawStage& raw, const std::string& top_candidate);

}  // namespace insmc::mc
