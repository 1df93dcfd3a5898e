// The benchmark's hand-written truth integrator must integrate the same
// equations as lib/truth's simulator, or the truth/reference time ratio of
// `insmc bench` would compare different work.
#include "montecarlo/study/bench/truth_reference.h"

#include <gtest/gtest.h>

#include "lib/truth/simulator.h"
#include "montecarlo/study/sampler/sampler.h"
#include "montecarlo/study/model/study_config.h"

namespace insmc::mc {
namespace {

// Both integrate the same steps; they differ only in round-off (operation
// order, r³ vs pow). The largest contribution is the gravitation difference
// G_c(r_c) − G(r), two ~9.8 m/s² terms: a relative 1e-16 per evaluation is
// 1e-15 m/s², which even as a constant bias over T = 84 min gives
// ½ · 1e-15 · 5040² ≈ 1.3e-8 m. The pulse remainder integral is continuous
// in its inputs, so round-off cannot flip a pulse into a finite jump. 1e-6 m
// leaves a factor 75 over that bound.
constexpr double kToleranceM = 1e-6;

void expect_same_errors(System system, double dv_pulse_mps, double bound_scale) {
  StudyConfig c;
  const std::vector<double> times = {0.0, 5.0, 42 * 60.0, 63 * 60.0, 84 * 60.0};
  TruthOptions o;
  o.model = c.model;
  o.system = system;
  o.dv_pulse_mps = dv_pulse_mps;
  o.filter_interval_s = c.test.filter_interval_s;
  const TruthReference reference(c.model, system, dv_pulse_mps, c.test.filter_interval_s, times, o.step_s);
  ASSERT_EQ(reference.outputs(), times.size());
  const Sampler sampler(c.uncertainties);
  for (std::uint64_t index = 0; index < 4; ++index) {
    const UncertaintyVector x = bound_scale * sampler.draw(c.seed, index);
    o.pulse_phase = Vec3(-0.5 + 0.3 * static_cast<double>(index), 0.1, 0.45 - 0.2 * static_cast<double>(index));
    const TruthRun run = simulate_truth(o, x, times);
    std::vector<Vec3> error(times.size());
    reference.run(x, o.pulse_phase, error.data());
    double largest_m = 0.0;
    for (std::size_t k = 0; k < times.size(); ++k) {
      largest_m = std::max(largest_m, run.position_error_ap_m[k].cwiseAbs().maxCoeff());
      EXPECT_LT((error[k] - run.position_error_ap_m[k]).cwiseAbs().maxCoeff(), kToleranceM)
          << "system " << system_number(system) << ", sample " << index << ", t = " << times[k] << " s";
    }
    EXPECT_GT(largest_m, 10.0) << "the comparison needs errors far above the tolerance";
  }
}

TEST(TruthReference, SamePositionErrorAsTheSimulatorWithPulses) {
  expect_same_errors(System::kTheodolite, 0.1 * kFtpsToMps, 1.0);
  expect_same_errors(System::kGyrocompass, 0.1 * kFtpsToMps, 1.0);
}

TEST(TruthReference, SamePositionErrorAtTenTimesTheBounds) {  // where the nonlinear terms matter
  expect_same_errors(System::kTheodolite, 0.1 * kFtpsToMps, 10.0);
  expect_same_errors(System::kGyrocompass, 0.1 * kFtpsToMps, 10.0);
}

TEST(TruthReference, SamePositionErrorWithContinuousOutput) {
  expect_same_errors(System::kTheodolite, 0.0, 1.0);
}

}  // namespace
}  // namespace insmc::mc
