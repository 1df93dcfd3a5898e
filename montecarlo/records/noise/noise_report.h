#pragma once
// The report of `insmc noise` (docs/noise.md §6): Markdown for people,
// allan.csv and noise_terms.csv for tables, noise.json for programs,
// the allan and stationarity figures (SVG and PNG) for the eye. Values in SI and in the units engineers quote
// (deg/sqrt(h), deg/h, m/s/sqrt(h), ug), beside Table 3.1's bounds.
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "lib/calibration/multiposition.h"
#include "lib/imu/imu_samples.h"
#include "montecarlo/records/noise/calibration_report.h"
#include "lib/noise/noise_analysis.h"
#include "montecarlo/report/report.h"

namespace insmc::noise {

/// A sensor's data-sheet values (`insmc noise --datasheet KEY=VALUE`), SI;
/// absent when not given. Drawn on the allan figure (the white noise as its
/// −1/2 slope N/√τ, the bias instability as its flat floor 0.664 B) and set
/// against the fitted terms in noise.md and noise.json.
struct Datasheet {
  std::optional<double> gyro_arw_radprts, gyro_bias_instability_radps;
  std::optional<double> accel_vrw_mpsprts, accel_bias_instability_mps2;
  bool empty() const {
    return !gyro_arw_radprts && !gyro_bias_instability_radps && !accel_vrw_mpsprts && !accel_bias_instability_mps2;
  }
  /// The sensor's white-noise and bias-instability values.
  std::optional<double> white(SensorKind kind) const;
  std::optional<double> instability(SensorKind kind) const;
};

/// Parses one `KEY=VALUE` (gyro_arw=0.15degprth, gyro_bias_instability=1degph,
/// accel_vrw=0.03mpsprth, accel_bias_instability=50ug) into `sheet`; throws
/// InputError naming --datasheet, the text and what is allowed.
void parse_datasheet_entry(const std::string& text, Datasheet& sheet);

/// noise's set: noise.md, allan.csv, noise_terms.csv, calibration.csv (the
/// multi-position calibrations, montecarlo/records/noise/calibration_report.h),
/// noise.json and the figures allan and stationarity
/// (montecarlo/records/noise/noise_figures.h); stdout noise.md (markdown) or
/// noise.json.
mc::ReportOutline noise_report_outline();

mc::Report noise_report(const SensorRecording& rec, const NoiseAnalysis& a, double confidence,
                    const Datasheet& sheet = {}, const std::vector<RecordingCalibration>& calibrations = {});

/// Fewest samples per recording: the Allan variance needs a few octaves of
/// cluster times, and the masking a few dozen blocks.
inline constexpr std::size_t kMinNoiseSamples = 300;

/// An InputError naming --input and the recording's file when it holds
/// fewer than kMinNoiseSamples (before any other is read).
void require_noise_samples(const ImuSamples& recording);

/// What `insmc noise` runs on its recordings.
struct NoiseStageOptions {
  NoiseOptions analysis;
  calibration::MultipositionOptions calibration;
  Datasheet sheet;
};

/// The noise stage of `recordings` (one per input file), in the order a
/// refusal costs least: the recordings' lengths (InputError naming --input,
/// at least kMinNoiseSamples each), their common sample grid, each one's
/// multi-position calibration where it holds enough still attitudes, then
/// the noise analysis of every channel (options.analysis.progress told each
/// stage); its report.
mc::Report noise_stage(std::vector<ImuSamples> recordings, const NoiseStageOptions& options);

}  // namespace insmc::noise
