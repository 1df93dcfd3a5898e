#pragma once
/// The figures of `insmc noise` (docs/noise.md), drawn by gnuplot
/// (montecarlo/report/plot/): the overlapping Allan deviation of each sensor
/// with its intervals and fitted model, and the stationarity check's block
/// means. Gyros in deg/h, accelerometers in µg, as the report's tables.
#include <array>
#include <optional>

#include "lib/noise/noise_analysis.h"
#include "lib/noise/recording.h"
#include "montecarlo/report/plot/panel_figure.h"

namespace insmc::noise {

/// A data sheet's values for one sensor kind (SI), when given: its white
/// noise (drawn as N/√τ) and bias instability (drawn as its floor 0.664 B).
struct SheetLevels {
  std::optional<double> white, instability;
};

/// `allan`: two log–log panels (gyros, accelerometers); per axis the Allan
/// deviation with its interval (shaded, bars) and the fitted model
/// (dashed); Table 3.1's bound and the data sheet's lines in the legend.
/// `sheet`: [gyro, accelerometer].
mc::PanelFigure noise_allan_figure(const NoiseAnalysis& a, const std::array<SheetLevels, 2>& sheet);

/// `stationarity`: per channel, each recording's block means minus its
/// mean after the first part, against time; the first part shaded, its
/// mean drawn across it (the stationarity test's statistic) inside the band
/// a first part like the rest stays in at the test's level (docs/noise.md §5).
mc::PanelFigure stationarity_figure(const SensorRecording& rec, const NoiseAnalysis& a);

}  // namespace insmc::noise
