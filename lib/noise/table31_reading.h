#pragma once
/// A channel's noise against Table 3.1 (docs/noise.md §4) from what the
/// report trusts: the fitted model where it passes its fit test, else the
/// IEEE slope readings (white noise, the floor as bias instability, the
/// +½ slope's random walk where one exists); a verdict only where the data
/// reach the horizon (one Schuler period): over a shorter record the ratio
/// is an extrapolation, and says how far.
#include "lib/noise/noise_analysis.h"

namespace insmc::noise {

enum class Table31Source { kFit, kSlopeReadings, kStuck };

struct Table31Reading {
  Table31Source source = Table31Source::kFit;
  double equivalent_si = 0;  ///< √Σ (each term as a constant over T_s)² [rad/s or m/s²]
  double ratio = 0;          ///< equivalent / Table 3.1's bound
  std::string largest_term;  ///< the term that contributes most
  bool extrapolated = false; ///< the longest stretch of data is shorter than T_s
  double extrapolation = 0;  ///< T_s / the longest stretch
};

Table31Reading table31_reading(const ChannelNoise& ch);

/// "the fit (passes its test)", "the IEEE slope readings (the fit fails its test)", "stuck".
std::string_view table31_source_text(Table31Source s);

}  // namespace insmc::noise
