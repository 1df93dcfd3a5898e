// Tests for montecarlo/gap/validation/foreign_layout.h: files in another
// recorder's conventions hold the same physics as insmc's own (f over a
// longer window is the mean of the shorter windows it spans; r does not
// depend on the sampling), and the record reader takes them as written.
#include "montecarlo/gap/validation/foreign_layout.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <set>

#include "lib/records/record_io.h"
#include "montecarlo/runs/simulation/record_simulation.h"

namespace insmc::gap {
namespace {

ForeignRuns short_runs() {
  ForeignRuns spec;
  spec.runs = 3;
  spec.nav_duration_s = 5400.0;
  return spec;
}

TEST(ForeignLayout, EveryCombinationComesRound) {
  std::set<std::tuple<double, double, bool, bool>> seen;
  for (std::uint64_t seed = 0; seed < 36; ++seed) {
    const ForeignLayout l = foreign_layout_of(seed, false);
    seen.insert({l.f_every_s, l.r_every_s, l.pulses, l.zero_row});
  }
  EXPECT_EQ(seen.size(), 3U * 3U * 2U * 2U);
  EXPECT_TRUE(foreign_layout_of(9, true).pulses) << "a quantization file keeps its pulses";
}

TEST(ForeignLayout, RowsFollowTheRecordersOwnGrids) {
  ForeignLayout layout;
  layout.f_every_s = 20.0;
  layout.r_every_s = 30.0;
  layout.pulses = false;
  layout.zero_row = true;
  const RecordFile file = simulate_foreign_file(TruthOptions{}, mc::Sampler(UncertaintyModel{}), 3, short_runs(), layout);
  EXPECT_EQ(file.header.find("dv_pulse_mps"), nullptr);
  EXPECT_EQ(file.header.find("filter_interval_s"), nullptr);
  EXPECT_TRUE(file.header.truth_entries.empty());
  ASSERT_EQ(file.runs.size(), 3U);
  for (std::size_t r = 0; r < file.runs.size(); ++r) {
    const RecordRun& run = file.runs[r];
    EXPECT_EQ(run.id, 100 + 7 * static_cast<std::int64_t>(r));
    EXPECT_EQ(run.rows.front().t_s, 0.0);
    EXPECT_FALSE(run.rows.front().has_f());
    for (const RecordRow& row : run.rows) {
      ASSERT_TRUE(row.r_ap_m.has_value()) << row.t_s;
      const bool on_f = std::fmod(row.t_s, 20.0) == 0.0 && row.t_s > 0;
      EXPECT_EQ(row.has_f(), on_f) << row.t_s;
      EXPECT_TRUE(on_f || std::fmod(row.t_s, 30.0) == 0.0) << row.t_s;
    }
  }
  // The third run stops 60-80 min into the navigation.
  EXPECT_EQ(file.runs[0].rows.back().t_s, 900.0 + 5400.0);
  EXPECT_GE(file.runs[2].rows.back().t_s, 900.0 + 3600.0 - 30.0);
  EXPECT_LE(file.runs[2].rows.back().t_s, 900.0 + 4800.0);
  // What insmc writes, it reads back as written (to the 9 digits kept).
  EXPECT_EQ(parse_record_text(write_record_file(file), "foreign.csv"), file);
}

TEST(ForeignLayout, ALongerWindowIsTheMeanOfTheWindowsItSpansAndRIsTheSame) {
  // Continuous f: the filter box's output over 20 s is the mean of its four
  // 5 s outputs (Δv adds up, fig. 5.2), and r(t) does not depend on how f is
  // sampled: two independent samplings of one run agree.
  ForeignLayout fine, coarse;
  fine.f_every_s = 5.0;
  coarse.f_every_s = 20.0;
  fine.r_every_s = coarse.r_every_s = 60.0;
  fine.pulses = coarse.pulses = false;
  ForeignRuns spec = short_runs();
  spec.runs = 1;
  const RecordRun a = simulate_foreign_file(TruthOptions{}, mc::Sampler(UncertaintyModel{}), 5, spec, fine).runs[0];
  const RecordRun b = simulate_foreign_file(TruthOptions{}, mc::Sampler(UncertaintyModel{}), 5, spec, coarse).runs[0];
  std::map<double, const RecordRow*> at;
  for (const RecordRow& row : a.rows) at[row.t_s] = &row;
  int compared = 0;
  for (const RecordRow& row : b.rows) {
    ASSERT_TRUE(at.count(row.t_s)) << row.t_s;
    for (int k = 0; k < 3; ++k)
      EXPECT_NEAR((*row.r_ap_m)[k], (*at[row.t_s]->r_ap_m)[k], 1e-6 * (1.0 + std::abs((*row.r_ap_m)[k]))) << row.t_s;
    if (!row.has_f()) continue;
    for (int k = 0; k < 3; ++k) {
      double mean = 0.0;
      for (int w = 0; w < 4; ++w) mean += *at.at(row.t_s - 5.0 * w)->f_mps2[k] / 4.0;
      EXPECT_NEAR(*row.f_mps2[k], mean, 1e-9 + 1e-6 * std::abs(mean)) << row.t_s << " axis " << k;
    }
    ++compared;
  }
  EXPECT_GT(compared, 300);
}

}  // namespace
}  // namespace insmc::gap
