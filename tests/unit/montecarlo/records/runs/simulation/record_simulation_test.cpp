// Truth-level runs as records: rows at the times asked for, test rows up to
// T and navigation after, and each run a pure function of (seed, run).
#include "montecarlo/records/runs/simulation/record_simulation.h"

#include <gtest/gtest.h>

#include "lib/uncertainty/uncertainty_model.h"

namespace insmc::runs {
namespace {

std::vector<double> every_10s(double end_s) {
  std::vector<double> t;
  for (double s = 10.0; s <= end_s + 1e-9; s += 10.0) t.push_back(s);
  return t;
}

bool same_rows(const RecordRun& a, const RecordRun& b) {
  if (a.rows.size() != b.rows.size()) return false;
  for (std::size_t i = 0; i < a.rows.size(); ++i)
    if (a.rows[i].t_s != b.rows[i].t_s || a.rows[i].f_mps2 != b.rows[i].f_mps2 || a.rows[i].r_ap_m != b.rows[i].r_ap_m)
      return false;
  return true;
}

TEST(RecordSimulation, RowsAtTheTimesAskedForTestUpToTNavigationAfter) {
  const mc::Sampler sampler{UncertaintyModel{}};
  const RecordRunSpec spec;  // T = 900 s, scheme none
  const std::vector<double> times = every_10s(1800.0);
  const RecordRun run = simulate_record_run(TruthOptions{}, sampler, 3, 5, times, spec);
  ASSERT_EQ(run.rows.size(), times.size());
  for (std::size_t i = 0; i < times.size(); ++i) {
    EXPECT_EQ(run.rows[i].t_s, times[i]);
    EXPECT_EQ(run.rows[i].phase, times[i] <= spec.test_duration_s ? Phase::kTest : Phase::kNav) << times[i];
    EXPECT_TRUE(run.rows[i].r_ap_m.has_value()) << times[i];
  }
}

TEST(RecordSimulation, ARunIsAPureFunctionOfSeedAndRunNumber) {
  const mc::Sampler sampler{UncertaintyModel{}};
  const std::vector<double> times = every_10s(1200.0);
  const RecordRun a = simulate_record_run(TruthOptions{}, sampler, 3, 5, times, {});
  EXPECT_TRUE(same_rows(a, simulate_record_run(TruthOptions{}, sampler, 3, 5, times, {})));
  EXPECT_FALSE(same_rows(a, simulate_record_run(TruthOptions{}, sampler, 3, 6, times, {})));
  EXPECT_FALSE(same_rows(a, simulate_record_run(TruthOptions{}, sampler, 4, 5, times, {})));
  // simulate_like on a run's own pattern gives that run back.
  EXPECT_TRUE(same_rows(a, simulate_like(a, TruthOptions{}, sampler, 3, 5, {})));
}

}  // namespace
}  // namespace insmc::runs
