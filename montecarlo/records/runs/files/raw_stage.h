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

#include "lib/noise/noise_fit.h"
#include "lib/records/record.h"

namespace insmc::runs {

struct RawChannel {
  std::string channel;        ///< gyro_x ... accel_z
  double equivalent_si = 0;   ///< rad/s or m/s²
  double ratio_to_bound = 0;  ///< against Table 3.1 (docs/noise.md §4)
  bool warm_up_excluded = false;
  /// Upper ends of the fitted intervals, in the candidates' terms (−1 when
  /// the term was not selected): the white noise after 1 h (N·√3600 s, rad
  /// or m/s) and the bias wander (the largest of B, K after 1 h, R over
  /// 1 h and the Gauss–Markov average over one Schuler period).
  double walk_1h_upper_si = -1, wander_upper_si = -1;
  /// What the Allan deviation allows them at most, selected or not (−1: not stated).
  double walk_1h_bound_si = -1, wander_bound_si = -1;
  /// The quantization's interval upper end, and the Allan bound on it.
  double quantization_upper_si = -1, quantization_bound_si = -1;
  /// The selected terms' fitted values (the null through the import
  /// synthesizes them, null/import_null.h).
  noise::NoiseModel model;
};

struct RawStage {
  std::vector<RawChannel> channels;
  double gyro_ratio = 0, accel_ratio = 0;  ///< the largest of each sensor
};

/// From the header; nullopt when the file holds no raw-stage keys.
std::optional<RawStage> raw_stage_from_header(const RecordHeader& header);

}  // namespace insmc::runs
