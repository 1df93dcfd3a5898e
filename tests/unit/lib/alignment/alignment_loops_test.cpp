// The alignment loops in the time domain against their steady state
// (2.10)/(2.14) as solved in lib/alignment (an independent algebraic
// solution), the torquer commands (5.14) and accelerometer outputs (5.19)
// against their steady-state maps, and the transient's decay.
#include "lib/alignment/alignment_loops.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "lib/alignment/alignment.h"
#include "lib/common/input_error.h"
#include "lib/uncertainty/catalogue.h"
#include "lib/units/units.h"
#include "tests/unit/lib/propagation/test_support.h"

namespace insmc {
namespace {

using testing::within_bounds;

TEST(AlignmentLoops, SettleToTheSteadyStateOfTheFullEquations) {
  // After 3 h every mode has decayed (slowest: system 2's azimuth integral,
  // minutes): C, ω_c and Δf_m equal the steady-state maps to 1e-9 rad,
  // 1e-4 meru and 1e-9 m/s² (round-off of the integration).
  const ModelOptions m;
  AlignmentLoopSettings s;
  s.duration_s = 3 * 3600.0;
  for (System sys : {System::kTheodolite, System::kGyrocompass}) {
    const Sensitivity3 steady = full_steady_state_misalignment(sys, m);
    for (std::uint64_t seed : {1u, 2u, 3u}) {
      const UncertaintyVector x = within_bounds(seed);
      const AlignmentLoopRun run = simulate_alignment_loops(sys, m, s, x);
      const Vec3 c = steady * x;
      EXPECT_LT((run.misalignment_rad - c).norm(), 1e-9) << system_number(sys) << " " << run.misalignment_rad.transpose()
                                                           << " vs " << c.transpose();
      EXPECT_LT((run.mean_command_radps - torquer_commands(steady, m) * x).norm(), 1e-4 * kMeruToRadps);
      EXPECT_LT((run.mean_accel_output_mps2 - alignment_accelerometer_outputs(steady, m) * x).norm(), 1e-9);
    }
  }
}

TEST(AlignmentLoops, CoarseErrorDecaysWithTheLoopsTimeConstants) {
  // Every uncertainty zero, a coarse error at the start: the level loops
  // (system 1: F(0) = 500 ω_ie behind a 10 s lag, time constant ≈ 30 s) leave
  // under 1 µrad of 1 mrad after 15 min; the gyrocompass of system 2 (a
  // triple pole at 82 s, and the initial level error swings the azimuth
  // first) leaves under 1 µrad after 30 min, more than 1 µrad after 5 min.
  const ModelOptions m;
  AlignmentLoopSettings s;
  const UncertaintyVector zero = UncertaintyVector::Zero();
  s.duration_s = 900.0;
  const AlignmentLoopRun level = simulate_alignment_loops(System::kTheodolite, m, s, zero);
  EXPECT_LT(level.misalignment_rad.head<2>().norm(), 1e-6);
  s.duration_s = 1800.0;
  EXPECT_LT(simulate_alignment_loops(System::kGyrocompass, m, s, zero).misalignment_rad.norm(), 1e-6);
  s.duration_s = 300.0;
  const double early = std::abs(simulate_alignment_loops(System::kGyrocompass, m, s, zero).misalignment_rad.z());
  EXPECT_GT(early, 1e-6);
  std::printf("  system 2 azimuth left after 5 min: %.3g mrad of 5 mrad\n", early * 1e3);
}

TEST(AlignmentLoops, DisturbingAccelerationsAreFiltered) {
  // (u)r̈ of 10 mg at 2 s period (sway) moves the level by far less than its
  // static equivalent 10 mrad: the loops filter it (F(0)/(1 + 10 p)).
  const ModelOptions m;
  AlignmentLoopSettings s;
  const std::function<Vec3(double)> sway = [&](double t) {
    return Vec3(0.0, 0.01 * m.gravity_mps2 * std::sin(M_PI * t), 0.0);
  };
  const AlignmentLoopRun run = simulate_alignment_loops(System::kTheodolite, m, s, UncertaintyVector::Zero(), sway);
  EXPECT_LT(std::abs(run.misalignment_rad.x()), 1e-5);
  EXPECT_GT(std::abs(run.misalignment_rad.x()), 0.0);
}

TEST(AlignmentLoops, SettingsAreValidated) {
  AlignmentLoopSettings s;
  s.duration_s = 0.0;
  EXPECT_THROW(validate(s), InputError);
  s = AlignmentLoopSettings{};
  s.step_s = 10.0;
  EXPECT_THROW(validate(s), InputError);
}

}  // namespace
}  // namespace insmc
