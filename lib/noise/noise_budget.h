#pragma once
/// A channel's fitted noise set against Table 3.1 (docs/noise.md §4): each
/// term as a constant rate error over one Schuler period T_s = 84.4 min,
/// root-sum-square over the terms, against the gyro drift bound ω_do or the
/// accelerometer bias change ∂f (the part of the bias the test run cannot
/// take out).
#include <string>

#include "lib/noise/noise_fit.h"

namespace insmc::noise {

/// One Schuler period, the report's flight horizon [s].
double schuler_period_s();
/// Table 3.1's bound for the in-run error of a channel [rad/s or m/s²].
double table31_bound_si(SensorKind kind);
/// The same in the paper's unit, e.g. "10 meru", "0.1 mg".
std::string table31_bound_text(SensorKind kind);
/// A term as a constant rate error over T_s: Q/T_s, N/√T_s, B, K√(T_s/3),
/// R T_s, and for the Gauss–Markov process the RMS of its average over T_s,
/// σ√(2x(1 − (1 − e^{−1/x})x)), x = T_c/T_s.
double equivalent_constant(NoiseTerm t, double value_si, double correlation_time_s);
/// √Σ equivalent_constant² of a fitted model.
double equivalent_constant(const NoiseModel& model);

}  // namespace insmc::noise
