#pragma once
// The multi-position calibration in the report of `insmc noise`
// (lib/calibration/multiposition.h, docs/noise.md §6): a Markdown section
// per recording that holds one, calibration.csv (every fitted parameter,
// SI and the units engineers quote) and noise.json's "calibration".
#include <string>
#include <vector>

#include "lib/calibration/multiposition.h"
#include "montecarlo/report/json.h"

namespace insmc::noise {

struct RecordingCalibration {
  std::string recording;  ///< the file name as given
  calibration::MultipositionCalibration result;
  double gravity_mps2 = 0;
};

/// Whether any recording holds a fitted calibration.
bool any_calibrated(const std::vector<RecordingCalibration>& calibrations);

/// The Markdown sections of the recordings whose calibration was fitted.
std::string calibration_markdown(const std::vector<RecordingCalibration>& calibrations, double confidence);
/// calibration.csv: a header and one row per fitted parameter.
std::string calibration_csv(const std::vector<RecordingCalibration>& calibrations);
mc::Json calibration_json(const std::vector<RecordingCalibration>& calibrations);

}  // namespace insmc::noise
