#pragma once
// The report of `insmc noise` (docs/noise.md §6): Markdown for people,
// allan.csv and noise_terms.csv for tables, noise.json for programs,
// allan.svg and stationarity.svg for the eye. Values in SI and in the units engineers quote
// (deg/sqrt(h), deg/h, m/s/sqrt(h), ug), beside Table 3.1's bounds.
#include <string>
#include <utility>
#include <vector>

#include "lib/noise/noise_analysis.h"
#include "montecarlo/write/json.h"

namespace insmc::app {

/// The value of a fitted term in the units engineers quote: (value, unit).
std::pair<double, std::string> spec_value(noise::NoiseTerm term, noise::SensorKind kind, double value_si);

/// The files of the report: noise.md first, then allan.csv, noise_terms.csv,
/// allan.svg, stationarity.svg.
std::vector<std::pair<std::string, std::string>> noise_report(const noise::SensorRecording& rec,
                                                              const noise::NoiseAnalysis& a, double confidence);
mc::Json noise_json(const noise::SensorRecording& rec, const noise::NoiseAnalysis& a, double confidence);

}  // namespace insmc::app
