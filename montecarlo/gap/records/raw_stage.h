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
#include "montecarlo/gap/candidates/candidates.h"

namespace insmc::mc {

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

/// "gyro", "accelerometer" or "" for an effect (or class "a|b") the
/// diagnosis ranked.
std::string sensor_of_effect(const std::string& effect);

/// The noise candidates limited to what the raw outputs allow (docs/gap.md
/// §4): angle_random_walk and velocity_random_walk to the raw white noise's
/// upper interval end, gyro_drift_instability and accel_bias_instability to
/// the raw bias wander's (or, when the stage selected no such term, to what
/// the Allan deviation allows it: the header's *_bound_si keys). So
/// a gyro error cannot be absorbed by an accelerometer candidate the raw
/// accelerometers rule out. The accelerometer quantization candidate's pulse
/// weight likewise to the raw velocity quantization. A candidate whose
/// sensor's raw outputs do not vary at all is left out. `statements` gets one line per limited candidate.
std::vector<gap::Candidate> limit_candidates(const std::vector<gap::Candidate>& candidates, const RawStage& raw,
                                             std::vector<std::string>& statements);

/// The statements for the report: the raw stage's verdict and, when the
/// navigation-level top candidate is of the other sensor than the one the
/// raw stage puts furthest outside Table 3.1, that they disagree.
std::vector<std::string> raw_stage_statements(const RawStage& raw, const std::string& top_candidate);

}  // namespace insmc::mc
