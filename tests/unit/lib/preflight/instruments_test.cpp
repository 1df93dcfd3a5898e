// The test run's instruments (lib/preflight/instruments.h) against what
// they must do by construction: a continuous ΔV output gives each
// interval's mean error exactly; a counter of pulse w loses no velocity (the
// interval errors sum, times τ, to the counted error, within one pulse of
// the true one at every interval) and reports whole pulses; the position
// readout is within half a resolution step of the truth at each reading, so
// its change from the first is within one step.
#include "lib/preflight/instruments.h"

#include <gtest/gtest.h>

#include <cmath>

namespace insmc {
namespace {

// Velocities since switch-over (zero at t = 0): a nominal one and an error
// that grows and wiggles.
double nominal_mps(double t) { return 9.81e-3 * t; }
double error_mps(double t) { return 2e-4 * t + 0.05 * std::sin(t / 130.0); }

TEST(Instruments, AContinuousCounterGivesEachIntervalsMeanErrorExactly) {
  DeltaVCounter counter(0.0, 0.0);
  const double tau = 10.0;
  double prev = 0.0;
  for (int k = 1; k <= 90; ++k) {
    const double t = k * tau;
    const double got = counter.interval_error_mps2(nominal_mps(t) + error_mps(t), nominal_mps(t) - nominal_mps(t - tau), tau);
    EXPECT_NEAR(got, (error_mps(t) - prev) / tau, 1e-15 * (1 + std::abs(nominal_mps(t)))) << k;
    prev = error_mps(t);
  }
}

TEST(Instruments, APulseCounterLosesNoVelocityAndReportsWholePulses) {
  const double w = 0.1 * 0.3048, tau = 10.0, phase = 0.3 * w;
  DeltaVCounter counter(w, phase);
  double counted_error = 0.0;
  for (int k = 1; k <= 90; ++k) {
    const double t = k * tau, t0 = t - tau;
    const double nominal_increment = nominal_mps(t) - nominal_mps(t0);
    const double d = counter.interval_error_mps2(nominal_mps(t) + error_mps(t), nominal_increment, tau);
    // Whole pulses: (d τ + nominal increment) is a multiple of w.
    const double pulses = (d * tau + nominal_increment) / w;
    EXPECT_NEAR(pulses, std::round(pulses), 1e-9) << k;
    counted_error += d * tau;
    // The running sum is the counted velocity less the nominal one: the
    // true error plus the starting remainder, less under one pulse.
    EXPECT_GT(counted_error, error_mps(t) + phase - w - 1e-12) << k;
    EXPECT_LE(counted_error, error_mps(t) + phase + 1e-12) << k;
  }
}

TEST(Instruments, ThePositionReadoutIsWithinOneStepOfTheTrueChange) {
  const double q = 3 * 0.3048;
  const double true0 = 1234.567, error0 = 0.42;
  const PositionReadout readout(q, true0, true0 + error0);
  for (int k = 1; k <= 90; ++k) {
    const double truth = true0 + 17.3 * k, error = error0 + 0.8 * std::sin(0.1 * k) + 0.05 * k;
    const double change = readout.change_m(truth, truth + error);
    EXPECT_LE(std::abs(change - (error - error0)), q + 1e-9) << k;
    // Each reading is a multiple of q: reading error + truth.
    const double reading = position_reading_error(truth, truth + error, q) + truth;
    EXPECT_NEAR(reading / q, std::round(reading / q), 1e-6) << k;
  }
  EXPECT_NEAR(PositionReadout(0.0, true0, true0 + error0).change_m(true0 + 5, true0 + 5 + 1.25), 1.25 - error0, 1e-12);
}

}  // namespace
}  // namespace insmc
