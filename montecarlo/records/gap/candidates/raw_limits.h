#pragma once
/// The candidates as the raw-sensor stage (runs/records/raw_stage.h) limits
/// them, and what the diagnosis says when the two levels point at different
/// sensors.
#include <string>
#include <vector>

#include "montecarlo/records/gap/candidates/candidates.h"
#include "montecarlo/records/runs/files/raw_stage.h"

namespace insmc::gap {

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
std::vector<Candidate> limit_candidates(const std::vector<Candidate>& candidates, const runs::RawStage& raw,
                                             std::vector<std::string>& statements);

/// The statements for the report: the raw stage's verdict and, when the
/// navigation-level top candidate is of the other sensor than the one the
/// raw stage puts furthest outside Table 3.1, that they disagree.
std::vector<std::string> raw_stage_statements(const runs::RawStage& raw, const std::string& top_candidate);

}  // namespace insmc::gap
