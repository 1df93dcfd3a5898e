// The gap metric G: each group's log ratio of observed to expected power,
// the scatter and the coherent groups.
#include "montecarlo/records/gap/metric/gap_metric.h"

#include <gtest/gtest.h>

#include <cmath>

#include "tests/unit/montecarlo/records/runs/test_layout.h"

namespace insmc::gap {
namespace {

using runs::testing::test_layout;

TEST(GapMetric, IsTheRmsOfTheGroupsLogRatiosAgainstTheCalibratedExpectation) {
  // One run: what it shares with itself is its own scatter (coherent ℓ = 0).
  Pooled one;
  one.runs = 1;
  for (int g = 0; g < 4; ++g) one.power.z2[g] = 10.0, one.power.count[g] = 10.0, one.power.expected[g] = 10.0;
  for (int g = 0; g < 4; ++g) one.coherent[static_cast<std::size_t>(runs::coherent_group_of(g))] += one.power.z2[g];
  NullCalibration none;
  EXPECT_DOUBLE_EQ(gap_value(one, none), 0.0);
  const int present = 4 + 4;  // four scatter groups and the four coherent groups they fall in
  one.power.z2[0] = 10.0 * std::exp(2.0);  // one group off by e² in power
  one.coherent[0] = one.power.z2[0];
  EXPECT_NEAR(gap_value(one, none), std::sqrt(4.0 / present), 1e-12);
  one.power.z2[1] = 10.0 * std::exp(-2.0);  // too little scatter counts as much as too much
  one.coherent[1] = one.power.z2[1];
  EXPECT_NEAR(gap_value(one, none), std::sqrt(8.0 / present), 1e-12);
  // The floor's share: a group whose actual expectation is 2 of 10 and
  // whose floor adds 8 expects 2 + κ 8.
  Pooled f;
  f.runs = 1;
  f.power.z2[0] = 6.0, f.power.count[0] = 10.0, f.power.expected[0] = 2.0, f.power.floor[0] = 8.0;
  NullCalibration half;
  half.floor_share[0] = 0.5;
  EXPECT_NEAR(log_ratios(f, half).scatter[0], 0.0, 1e-12);
  // The floor is an allowance: anything from the actual expectation (2,
  // the linear level without second-order terms) to 2 + κ 8 agrees; beyond
  // either end the ratio is to that end.
  for (double inside : {2.0, 3.0, 6.0}) {
    f.power.z2[0] = inside;
    EXPECT_DOUBLE_EQ(log_ratios(f, half).scatter[0], 0.0) << inside;
  }
  f.power.z2[0] = 0.5;
  EXPECT_NEAR(log_ratios(f, half).scatter[0], std::log(0.5 / 2.0), 1e-12);
  f.power.z2[0] = 12.0;
  EXPECT_NEAR(log_ratios(f, half).scatter[0], std::log(12.0 / 6.0), 1e-12);
}

TEST(GapMetric, CoherentGroupsSeeOnlyWhatRunsShareBeyondIndependence) {
  // Two runs with the same values in a group share all of it: C = 2 D, ℓ = ln 2;
  // opposite values share nothing positive: one-sided, ℓ = 0.
  runs::KeySpace keys;
  runs::Layout l;
  for (int k = 0; k < 3; ++k) l.rows.push_back({60.0, runs::Quantity::kR, k, group_of(runs::Stage::kTest, runs::Quantity::kR, k, 0)});
  l.test_rows = 3;
  keys.add_layout(l);
  Eigen::MatrixXd same = Eigen::MatrixXd::Zero(keys.size(), 2), opposite = same;
  same(0, 0) = same(0, 1) = 1.5;
  opposite(0, 0) = 1.5, opposite(0, 1) = -1.5;
  runs::GroupSums run;
  const int g = group_of(runs::Stage::kTest, runs::Quantity::kR, 0, 0), c = runs::coherent_group_of(g);
  run.z2[g] = 2.25, run.count[g] = 1.0, run.expected[g] = 2.25;
  const std::vector<int> both = {0, 1};
  const NullCalibration none;
  EXPECT_NEAR(log_ratios(pool(make_run_set({run, run}, same, keys), both), none).coherent[static_cast<std::size_t>(c)],
              std::log(2.0), 1e-12);
  EXPECT_NEAR(log_ratios(pool(make_run_set({run, run}, opposite, keys), both), none).coherent[static_cast<std::size_t>(c)],
              0.0, 1e-12);
  // A multiset counts a repeated run twice: three copies share 3 D.
  EXPECT_NEAR(log_ratios(pool(make_run_set({run, run}, same, keys), std::vector<int>{0, 0, 1}), none)
                  .coherent[static_cast<std::size_t>(c)],
              std::log(3.0), 1e-12);
  // Runs alike to the last digit but a hundred times below the model's
  // scatter (a perfect sensor) share nothing the model would notice: the
  // reference is the model's scatter then, and with 200 such runs the
  // shared part reaches it only at 200 × 1e-4 / 2.25 < 1.
  runs::GroupSums tiny = run;
  tiny.z2[g] = 1e-4;
  Eigen::MatrixXd alike = Eigen::MatrixXd::Zero(keys.size(), 200);
  alike.row(0).setConstant(1e-2);
  std::vector<int> all(200);
  for (int k = 0; k < 200; ++k) all[static_cast<std::size_t>(k)] = k;
  const auto significance = CoherentReference::kAtLeastModelScatter;
  EXPECT_NEAR(log_ratios(pool(make_run_set(std::vector<runs::GroupSums>(200, tiny), alike, keys), all), none, significance)
                  .coherent[static_cast<std::size_t>(c)],
              0.0, 1e-12);
  // Comparing candidates, the runs' own scatter stays the reference: a
  // candidate that only widens the model cannot explain what runs share.
  EXPECT_NEAR(log_ratios(pool(make_run_set(std::vector<runs::GroupSums>(200, tiny), alike, keys), all), none)
                  .coherent[static_cast<std::size_t>(c)],
              std::log(200.0), 1e-9);
  // … and when what they share outgrows the model's scatter, it counts:
  // 200 runs × 0.04 = 8 against the model's 2.25.
  tiny.z2[g] = 0.04;
  alike.row(0).setConstant(0.2);
  EXPECT_NEAR(log_ratios(pool(make_run_set(std::vector<runs::GroupSums>(200, tiny), alike, keys), all), none, significance)
                  .coherent[static_cast<std::size_t>(c)],
              std::log(200 * 0.04 / 2.25), 1e-9);
  // Null runs that share a systematic part calibrate it away: λ from their
  // pairs over the floor one run contributes.
  runs::GroupSums floored = run;
  floored.floor[g] = 2.25;
  const RunSet null = make_run_set({floored, floored}, same, keys);
  const NullCalibration cal = NullCalibration::from_null(null);
  EXPECT_NEAR(cal.systematic[static_cast<std::size_t>(c)], 1.0, 1e-12);  // pairs 2.25 over floor 2.25
  EXPECT_NEAR(cal.floor_share[g], 0.0, 1e-12);  // z² = the actual expectation: the floor adds nothing
  // κ: the share of the floor the null's z² shows, (z² − expected) / floor.
  runs::GroupSums half_floored = floored;
  half_floored.z2[g] = 2.25 + 0.5 * 2.25;
  EXPECT_NEAR(NullCalibration::from_null(make_run_set({half_floored, half_floored}, same, keys)).floor_share[g], 0.5,
              1e-12);
  EXPECT_NEAR(log_ratios(pool(null, both), cal).coherent[static_cast<std::size_t>(c)], 0.0, 1e-12);
}

TEST(GapMetric, ALargeSetPoolsAsItsPairsWould) {
  // Beyond kMaxGramRuns a set keeps the runs' values, not every pair's
  // inner products: a multiset pools to Σ_a Σ_b z_a·z_b all the same, and
  // the null's pairs of different runs are |Σ z|² − Σ |z|².
  runs::KeySpace keys;
  runs::Layout l;
  for (int k = 0; k < 3; ++k)
    l.rows.push_back({60.0 * (k + 1), runs::Quantity::kR, k, group_of(runs::Stage::kTest, runs::Quantity::kR, k, 0)});
  l.test_rows = 3;
  keys.add_layout(l);
  const int n = kMaxGramRuns + 44;
  Eigen::MatrixXd z(keys.size(), n);
  for (int r = 0; r < n; ++r)
    for (int k = 0; k < keys.size(); ++k) z(k, r) = std::sin(1.0 + 0.37 * r + 1.3 * k);
  const RunSet large = make_run_set(std::vector<runs::GroupSums>(static_cast<std::size_t>(n)), z, keys);
  EXPECT_EQ(large.gram[0].size(), 0);
  const std::vector<int> multiset = {3, 7, 7, 250, 299};
  for (int c = 0; c < runs::kCoherentCount; ++c) {
    double pairs = 0.0, distinct = 0.0;
    for (int k = 0; k < keys.size(); ++k) {
      if (keys.coherent_group(k) != c) continue;
      for (int a : multiset)
        for (int b : multiset) pairs += z(k, a) * z(k, b);
      const double total = z.row(k).sum();
      distinct += total * total - z.row(k).squaredNorm();
    }
    EXPECT_NEAR(large.pair_sum(c, multiset), pairs, 1e-12 * (1 + std::abs(pairs))) << c;
    EXPECT_NEAR(large.distinct_pair_sum(c), distinct, 1e-10 * (1 + std::abs(distinct))) << c;
  }
}

}  // namespace
}  // namespace insmc::gap
