#pragma once
/// The preflight test run's instruments (fig. 5.2, §4.3), one axis each:
/// what they record of the errors, with their quantization. The Monte Carlo
/// sample path, the truth level's estimates and the record writers read the
/// data through these, so the observation model is written once; the
/// estimators that turn the data into Û2, Û3, Δf̂(T) are apply_estimators
/// (test_run.h).
#include <cmath>

#include "lib/preflight/observables.h"

namespace insmc {

/// The position computer's reading error at resolution q: its output (the
/// nearest multiple of q to the indicated position, true + error) less the
/// known true position.
inline double position_reading_error(double true_m, double indicated_m, double resolution_m) {
  return at_resolution(indicated_m, resolution_m) - true_m;
}

/// The position computer through a test run: each reading's error as a
/// change from the first reading's, the Δr_k that (4.7), (4.8) fit.
class PositionReadout {
 public:
  PositionReadout(double resolution_m, double true_at_start_m, double indicated_at_start_m)
      : resolution_m_(resolution_m),
        first_m_(position_reading_error(true_at_start_m, indicated_at_start_m, resolution_m)) {}
  double change_m(double true_m, double indicated_m) const {
    return position_reading_error(true_m, indicated_m, resolution_m_) - first_m_;
  }

 private:
  double resolution_m_, first_m_;
};

/// A ΔV pulse counter through the filter box (fig. 5.2): it counts the
/// velocity since switch-over, nominal + error, in whole pulses from its
/// starting remainder (phase), and each filter interval's data is the
/// counted increment less the known nominal increment, over τ: the
/// interval-averaged Δf error. pulse = 0: a continuous output.
class DeltaVCounter {
 public:
  DeltaVCounter(double pulse_mps, double phase_mps) : pulse_mps_(pulse_mps), phase_mps_(phase_mps) {}
  /// `velocity_mps`: nominal + error at the interval's end; returns the
  /// interval's Δf error [m/s²].
  double interval_error_mps2(double velocity_mps, double nominal_increment_mps, double interval_s) {
    const double counted =
        pulse_mps_ > 0 ? pulse_mps_ * std::floor((velocity_mps + phase_mps_) / pulse_mps_) : velocity_mps;
    const double out = (counted - counted_mps_ - nominal_increment_mps) / interval_s;
    counted_mps_ = counted;
    return out;
  }

 private:
  double pulse_mps_, phase_mps_, counted_mps_ = 0.0;
};

}  // namespace insmc
