// Tests for montecarlo/records/gap/validation/writer_conventions.h: files in another
// recorder's conventions hold the same physics as insmc's own (f over a
// longer window is the mean of the shorter windows it spans; r does not
// depend on the sampling), and the record reader takes them as written.
#include "montecarlo/records/gap/validation/writer_conventions.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "lib/records/record_io.h"
#include "montecarlo/records/gap/metric/run_set.h"
#include "montecarlo/records/runs/prepared_runs.h"
#include "montecarlo/records/runs/simulation/record_simulation.h"

namespace insmc::gap {
namespace {

ForeignRuns short_runs() {
  ForeignRuns spec;
  spec.runs = 3;
  spec.nav_duration_s = 5400.0;
  return spec;
}

TEST(WriterConventions, EveryCombinationComesRound) {
  std::set<std::tuple<double, double, bool, bool>> seen;
  for (std::uint64_t seed = 0; seed < 36; ++seed) {
    const WriterConventions l = foreign_conventions_of(seed, false);
    seen.insert({l.f_every_s, l.r_every_s, l.pulses, l.zero_row});
  }
  EXPECT_EQ(seen.size(), 3U * 3U * 2U * 2U);
  EXPECT_TRUE(foreign_conventions_of(9, true).pulses) << "a quantization file keeps its pulses";
}

TEST(WriterConventions, RowsFollowTheRecordersOwnGrids) {
  WriterConventions conventions;
  conventions.f_every_s = 20.0;
  conventions.r_every_s = 30.0;
  conventions.pulses = false;
  conventions.zero_row = true;
  const RecordFile file = simulate_foreign_file(TruthOptions{}, mc::Sampler(UncertaintyModel{}), 3, short_runs(), conventions);
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

TEST(WriterConventions, ALongerWindowIsTheMeanOfTheWindowsItSpansAndRIsTheSame) {
  // Continuous f: the filter box's output over 20 s is the mean of its four
  // 5 s outputs (Δv adds up, fig. 5.2), and r(t) does not depend on how f is
  // sampled: two independent samplings of one run agree.
  WriterConventions fine, coarse;
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

TEST(FuzzedLayout, DrawsEveryConventionOverItsRange) {
  std::set<double> f_every, r_every;
  int pulses = 0, zero_rows = 0, f_in_nav = 0, exact = 0, keys = 0;
  double least_resolution = 1e300, largest_resolution = 0.0, largest_dropout = 0.0;
  std::set<double> short_shares;
  constexpr int kFiles = 400;
  for (std::uint64_t seed = 0; seed < kFiles; ++seed) {
    const WriterConventions l = fuzzed_conventions_of(seed, false, 900.0);
    ASSERT_GE(l.f_every_s, 1.0);
    ASSERT_LE(l.f_every_s, 60.0);
    ASSERT_GE(l.r_every_s, 1.0);
    ASSERT_LE(l.r_every_s, 60.0);
    ASSERT_GE(l.dropout_max, 0.0);
    ASSERT_LE(l.dropout_max, 0.1);
    f_every.insert(l.f_every_s);
    r_every.insert(l.r_every_s);
    pulses += l.pulses, zero_rows += l.zero_row, f_in_nav += l.f_in_nav, keys += l.header_keys;
    if (l.resolution_m == 0.0) ++exact;
    else least_resolution = std::min(least_resolution, l.resolution_m), largest_resolution = std::max(largest_resolution, l.resolution_m);
    largest_dropout = std::max(largest_dropout, l.dropout_max);
    short_shares.insert(l.short_share);
    EXPECT_EQ(l.short_from_s, 450.0);
  }
  // Each whole second of 1-60 s has probability 1/60 a draw: in 400 draws a
  // value is never drawn with probability (59/60)^400 = 1.2e-3, so fewer than
  // 50 distinct values (11 never drawn) has probability below C(60,11)
  // (1.2e-3)^11 < 1e-20. The bounds below are each 4.5 standard deviations
  // or more from their binomial mean, or a miss of probability < 1e-6.
  EXPECT_GE(f_every.size(), 50U);
  EXPECT_GE(r_every.size(), 50U);
  // Coins: 400 draws of probability 1/2 lie in [150, 250] but with probability < 1e-6 (binomial).
  for (const int heads : {pulses, zero_rows, f_in_nav, keys}) {
    EXPECT_GE(heads, 150);
    EXPECT_LE(heads, 250);
  }
  EXPECT_GE(exact, 60);  // p = 1/4: mean 100, sd 8.7
  EXPECT_LT(least_resolution, 2e-4);
  EXPECT_GT(largest_resolution, 0.6);
  EXPECT_GT(largest_dropout, 0.095);
  EXPECT_EQ(short_shares.size(), 4U);
  EXPECT_TRUE(fuzzed_conventions_of(7, true, 900.0).pulses) << "a quantization file keeps its pulses";
}

/// `runs` runs of f and r every 10 s (continuous f), each dropping up to
/// 10 % of its records its own way, none short.
RecordFile own_dropouts_file(int runs, std::uint64_t seed) {
  WriterConventions conventions;
  conventions.f_every_s = 10.0;
  conventions.r_every_s = 10.0;
  conventions.pulses = false;
  conventions.dropout_max = 0.1;
  conventions.short_share = 0.0;
  conventions.short_from_s = 450.0;
  ForeignRuns spec = short_runs();
  spec.runs = runs;
  return simulate_foreign_file(TruthOptions{}, mc::Sampler(UncertaintyModel{}), seed, spec, conventions);
}

/// The diagnosis' runs of `file` (runs/prepared_runs.h).
runs::PreparedRuns prepared(const RecordFile& file) {
  runs::RecordReading reading;
  std::vector<std::string> statements;
  std::vector<runs::SiteValue> site;
  return runs::prepare(runs::read_records(file, reading, statements, site), reading);
}

TEST(FuzzedLayout, EachRunDropsRecordsOfItsOwnAndTheModelIsBuiltOnce) {
  const RecordFile file = own_dropouts_file(6, 21);
  ASSERT_EQ(file.runs.size(), 6U);
  std::set<std::vector<double>> patterns;
  for (const RecordRun& run : file.runs) {
    std::vector<double> missing;  // rows without f, and rows lost (the grid every 10 s)
    double expected = run.rows.front().t_s;
    for (const RecordRow& row : run.rows) {
      for (; expected < row.t_s - 1e-9; expected += 10.0) missing.push_back(-expected);
      if (!row.has_f()) missing.push_back(row.t_s);
      expected = row.t_s + 10.0;
    }
    patterns.insert(missing);
  }
  EXPECT_EQ(patterns.size(), 6U) << "every run its own dropouts";
  EXPECT_EQ(parse_record_text(write_record_file(file), "fuzzed.csv"), file);
  // The diagnosis' run model: a layout per run, one lattice for all, from
  // which every layout takes its rows (runs/prepared_runs.h).
  const runs::PreparedRuns p = prepared(file);
  EXPECT_GT(p.layouts.size(), 1U);
  EXPECT_EQ(p.lattices.size(), 1U);
  for (std::size_t L = 0; L < p.layouts.size(); ++L) EXPECT_EQ(p.lattice_of[L], 0);
}

TEST(FuzzedLayout, RunsEvaluatedOneLayoutModelAtATimeAreThoseUnderEveryModelKept) {
  // A layout per run: the evaluation that builds and drops one layout's
  // model at a time (memory of one model) must give each run the values
  // of its own layout's model, in the runs' order, to the bit.
  runs::PreparedRuns p = prepared(own_dropouts_file(5, 22));
  ASSERT_GT(p.layouts.size(), 2U);
  // Runs out of their layouts' order, one layout twice.
  std::reverse(p.runs.begin(), p.runs.end());
  std::reverse(p.layout_of.begin(), p.layout_of.end());
  p.runs.push_back(p.runs.front());
  p.layout_of.push_back(p.layout_of.front());
  const std::vector<std::optional<runs::RunAnalyser>> kept = runs::layout_analysers(p, {});
  std::vector<const runs::RunAnalyser*> pointers;
  for (const std::optional<runs::RunAnalyser>& a : kept) pointers.push_back(&*a);
  const EvaluatedRuns all_kept = evaluate_runs(p.runs, p.layout_of, pointers, p.keys);
  const EvaluatedRuns one_at_a_time = evaluate_runs(p, {}, std::vector<bool>(p.layouts.size(), true));
  ASSERT_EQ(one_at_a_time.sums.size(), p.runs.size());
  for (std::size_t r = 0; r < p.runs.size(); ++r)
    for (int g = 0; g < runs::kGroupCount; ++g) {
      EXPECT_EQ(one_at_a_time.sums[r].z2[g], all_kept.sums[r].z2[g]) << "run " << r << " group " << g;
      EXPECT_EQ(one_at_a_time.sums[r].expected[g], all_kept.sums[r].expected[g]) << "run " << r << " group " << g;
    }
  EXPECT_TRUE(one_at_a_time.keyed == all_kept.keyed);
  EXPECT_NE(one_at_a_time.keyed.col(0), one_at_a_time.keyed.col(1)) << "runs of their own values";
}

}  // namespace
}  // namespace insmc::gap
