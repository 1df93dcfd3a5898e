// Short filter windows summed into longer ones (montecarlo/records/runs/files/filter_windows.h):
// the result is what a box of the longer window counts, blocks end on the
// test run's grid, and a block with a gap, an off-grid spacing or a phase
// change is left out.
#include "montecarlo/records/runs/files/filter_windows.h"

#include <gtest/gtest.h>

#include <cmath>

namespace insmc::runs {
namespace {

constexpr double kPulseMps = 0.03048;

/// Pulses counted by time t from a velocity with drift, a wave and an offset
/// (a sawtooth remainder carried, as a pulse counter does).
double counted_velocity_mps(double t_s, int axis) {
  const double v = (1e-3 + 2e-4 * axis) * t_s + 0.05 * std::sin(0.7 * t_s + axis) + 0.013 * axis;
  return kPulseMps * std::floor(v / kPulseMps);
}

/// One run of f rows every τ from τ to end_s: the count over each window / τ.
RecordRun counted_run(double tau_s, double test_s, double end_s) {
  RecordRun run;
  run.id = 4;
  for (long i = 1; i * tau_s <= end_s + 1e-9; ++i) {
    RecordRow row;
    row.run = run.id;
    row.t_s = static_cast<double>(i) * tau_s;
    row.phase = row.t_s <= test_s + 1e-9 ? Phase::kTest : Phase::kNav;
    for (int k = 0; k < 3; ++k)
      row.f_mps2[static_cast<std::size_t>(k)] =
          (counted_velocity_mps(row.t_s, k) - counted_velocity_mps(row.t_s - tau_s, k)) / tau_s;
    run.rows.push_back(row);
  }
  return run;
}

TEST(FilterWindows, SummedWindowsAreWhatTheLongerBoxCounts) {
  const double tau = 0.1, T = 30.0;
  RecordFile file;
  file.runs.push_back(counted_run(tau, T, 45.0));
  const FilterWindows w = coarsen_filter_windows(file, tau, T, 1.0);
  EXPECT_EQ(w.factor, 10);
  EXPECT_DOUBLE_EQ(w.tau_s, 1.0);
  EXPECT_EQ(w.dropped, 0);
  int kept = 0;
  for (const RecordRow& row : file.runs[0].rows) {
    const bool block_end = std::abs(row.t_s - std::round(row.t_s)) < 1e-6;
    for (int k = 0; k < 3; ++k) {
      const auto& f = row.f_mps2[static_cast<std::size_t>(k)];
      ASSERT_EQ(f.has_value(), block_end) << "t " << row.t_s;
      if (!f) continue;
      ++kept;
      const double box = (counted_velocity_mps(row.t_s, k) - counted_velocity_mps(row.t_s - 1.0, k)) / 1.0;
      EXPECT_NEAR(*f, box, 1e-12) << "t " << row.t_s << " axis " << k;
    }
  }
  EXPECT_EQ(kept, 3 * 45);
}

TEST(FilterWindows, ABlockWithAGapOrAPhaseChangeIsLeftOut) {
  // T/τ = 41 windows, prime: blocks of 4 on the 1 s grid, and (10, 11] holds
  // the test window ending at T = 10.25 and three navigation windows.
  const double tau = 0.25, T = 10.25;
  RecordFile file;
  file.runs.push_back(counted_run(tau, T, 12.0));
  auto& rows = file.runs[0].rows;
  rows[9].f_mps2[1].reset();  // t = 2.5: a gap in y's block (2, 3]
  const FilterWindows w = coarsen_filter_windows(file, tau, T, 1.0);
  EXPECT_EQ(w.factor, 4);
  for (const RecordRow& row : rows) {
    if (std::abs(row.t_s - 3.0) < 1e-9) {
      EXPECT_TRUE(row.f_mps2[0] && row.f_mps2[2]);
      EXPECT_FALSE(row.f_mps2[1]) << "the block with the gap";
    }
    if (row.t_s > 10.0 && row.t_s < 11.0 + 1e-9) {
      EXPECT_FALSE(row.has_f()) << "t " << row.t_s << " across T";
    }
    if (std::abs(row.t_s - 12.0) < 1e-9) {
      EXPECT_TRUE(row.f_mps2[0]) << "a whole navigation block";
    }
  }
  EXPECT_EQ(w.dropped, 3 + 3 * 4);  // y's three values beside the gap; the four across T, per axis
}

TEST(FilterWindows, BlocksEndOnTheTestRunsGridAndLongWindowsAreLeftAlone) {
  RecordFile file;
  file.runs.push_back(counted_run(0.3, 9.0, 9.0));
  // T/τ = 30 windows: 4 does not divide 30, 5 does (1.5 s blocks end at T).
  EXPECT_EQ(coarsen_filter_windows(file, 0.3, 9.0, 1.0).factor, 5);
  EXPECT_TRUE(file.runs[0].rows.back().f_mps2[0]) << "the last block ends at T";

  RecordFile ten;
  ten.runs.push_back(counted_run(10.0, 900.0, 1000.0));
  const RecordFile before = ten;
  const FilterWindows w = coarsen_filter_windows(ten, 10.0, 900.0, 1.0);
  EXPECT_EQ(w.factor, 1);
  EXPECT_DOUBLE_EQ(w.tau_s, 10.0);
  for (std::size_t i = 0; i < ten.runs[0].rows.size(); ++i)
    EXPECT_EQ(ten.runs[0].rows[i].f_mps2, before.runs[0].rows[i].f_mps2);
}

}  // namespace
}  // namespace insmc::runs
