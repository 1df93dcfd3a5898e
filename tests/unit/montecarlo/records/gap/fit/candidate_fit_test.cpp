// A candidate's grid evaluation (montecarlo/records/gap/fit/candidate_fit.h)
// keeps each grid point's run set and drops the runs' keyed values; the
// points a choice takes are evaluated again (keep_keyed_at). The values
// evaluated again must be those the run set was made from, to the bit, on
// runs of two layouts cut from one lattice. Several sets of runs evaluated
// together (the records and the null files) must each get what they get
// alone, to the bit.
#include "montecarlo/records/gap/fit/candidate_fit.h"

#include <gtest/gtest.h>

#include <random>
#include <stdexcept>
#include <string>

#include "lib/uncertainty/uncertainty_model.h"
#include "tests/unit/montecarlo/records/runs/test_layout.h"

namespace insmc::gap {
namespace {

const Candidate& candidate(const std::string& name) {
  for (const Candidate& c : candidate_registry())
    if (c.name == name) return c;
  throw std::runtime_error("no candidate " + name);
}

/// Runs of a long layout and a shorter one with values drawn at random (the
/// test compares bits, not statistics).
runs::PreparedRuns two_layout_runs() {
  runs::PreparedRuns p;
  p.site = runs::testing::test_site();
  p.x_var = UncertaintyModel{}.variance();
  std::mt19937_64 rng(7);
  std::normal_distribution<double> normal;
  for (int r = 0; r < 10; ++r) {
    const double end_s = r % 3 == 0 ? 1800.0 : 2700.0;
    const runs::Layout l = runs::testing::test_layout(end_s);
    const int L = p.layout_index(l);
    std::vector<double> values(l.rows.size());
    for (double& v : values) v = normal(rng);
    p.runs.push_back({r, l, std::move(values), end_s});
    p.layout_of.push_back(L);
  }
  return p;
}

TEST(GapCandidateFit, TheKeyedValuesEvaluatedAgainAreThoseTheGridPointsRunSetWasMadeFrom) {
  const runs::PreparedRuns p = two_layout_runs();
  ASSERT_EQ(p.layouts.size(), 2U);
  NullCalibration m0;
  m0.floor_share.fill(1.0);
  m0.systematic.fill(0.0);
  const std::vector<std::vector<runs::Extension>> none(p.lattices.size());
  CandidateSums s = evaluate_candidate(p, candidate("bounds"), none, m0);
  std::vector<int> all(p.runs.size());
  for (std::size_t r = 0; r < all.size(); ++r) all[r] = static_cast<int>(r);
  int checked = 0;
  for (int k = 0; k < s.grid_size(); ++k) {
    if (!s.evaluated[static_cast<std::size_t>(k)]) continue;
    EXPECT_FALSE(s.keyed_kept[static_cast<std::size_t>(k)]) << "grid point " << k << " kept its keyed values";
    keep_keyed_at(s, {k});
    ASSERT_TRUE(s.keyed_kept[static_cast<std::size_t>(k)]);
    Choice at;
    at.grid = k;
    const RunSet again = run_set_under(s, all, std::vector<Choice>(all.size(), at));
    const RunSet& first = s.sets[static_cast<std::size_t>(k)];
    for (int c = 0; c < runs::kCoherentCount; ++c)
      EXPECT_TRUE(again.gram[static_cast<std::size_t>(c)] == first.gram[static_cast<std::size_t>(c)])
          << "grid point " << k << ", coherent group " << c;
    for (std::size_t r = 0; r < all.size(); ++r)
      EXPECT_TRUE(again.sums[r].z2 == first.sums[r].z2 && again.sums[r].expected == first.sums[r].expected)
          << "grid point " << k << ", run " << r;
    ++checked;
  }
  EXPECT_GE(checked, 2);
}

/// The same layouts with other values: a second set of runs.
runs::PreparedRuns redrawn(runs::PreparedRuns p, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> normal;
  for (runs::RunData& r : p.runs)
    for (double& v : r.values) v = normal(rng);
  return p;
}

void expect_same_sums(const CandidateSums& together, const CandidateSums& alone, const std::string& what) {
  ASSERT_EQ(together.amplitudes, alone.amplitudes) << what;
  if (alone.amplitudes) {
    ASSERT_EQ(together.normalized.size(), alone.normalized.size()) << what;
    for (std::size_t r = 0; r < alone.normalized.size(); ++r)
      EXPECT_TRUE(together.normalized[r] == alone.normalized[r]) << what << ", run " << r;
    ASSERT_EQ(together.signature.size(), alone.signature.size()) << what;
    for (std::size_t k = 0; k < alone.signature.size(); ++k)
      for (std::size_t L = 0; L < alone.signature[k].size(); ++L)
        EXPECT_TRUE(together.signature[k][L] == alone.signature[k][L]) << what << ", point " << k << ", layout " << L;
    return;
  }
  EXPECT_EQ(together.evaluated, alone.evaluated) << what << ": the points its own search asked for";
  for (std::size_t k = 0; k < alone.evaluated.size(); ++k) {
    if (!alone.evaluated[k]) continue;
    for (int c = 0; c < runs::kCoherentCount; ++c)
      EXPECT_TRUE(together.sets[k].gram[static_cast<std::size_t>(c)] == alone.sets[k].gram[static_cast<std::size_t>(c)])
          << what << ", point " << k << ", coherent group " << c;
    for (std::size_t r = 0; r < alone.sets[k].sums.size(); ++r)
      EXPECT_TRUE(together.sets[k].sums[r].z2 == alone.sets[k].sums[r].z2 &&
                  together.sets[k].sums[r].expected == alone.sets[k].sums[r].expected)
          << what << ", point " << k << ", run " << r;
  }
}

TEST(GapCandidateFit, SetsOfRunsEvaluatedTogetherEachGetWhatTheyGetAlone) {
  const runs::PreparedRuns p = two_layout_runs();
  const runs::PreparedRuns q = redrawn(p, 11);
  NullCalibration m0;
  m0.floor_share.fill(1.0);
  m0.systematic.fill(0.0);
  const std::vector<std::vector<runs::Extension>> none(p.lattices.size());
  // The second set searched as two files of five runs, as null files are.
  const std::vector<std::vector<int>> files = {{0, 1, 2, 3, 4}, {5, 6, 7, 8, 9}};
  const runs::PreparedRuns* parts[] = {&p, &q};
  const Candidate* amplitude = nullptr;
  for (const Candidate& c : candidate_registry())
    if (!c.amplitude_indices().empty()) amplitude = &c;
  ASSERT_NE(amplitude, nullptr);
  bool searches_differ = false;
  for (const Candidate* c : {&candidate("bounds"), &candidate("gyro_drift_instability"), amplitude}) {
    std::vector<CandidateSums> together = evaluate_candidate(parts, *c, none, m0, {{}, files});
    ASSERT_EQ(together.size(), 2U);
    CandidateSums alone_p = evaluate_candidate(p, *c, none, m0);
    CandidateSums alone_q = evaluate_candidate(q, *c, none, m0, files);
    expect_same_sums(together[0], alone_p, c->name + ", first set");
    expect_same_sums(together[1], alone_q, c->name + ", second set");
    searches_differ = searches_differ || alone_p.evaluated != alone_q.evaluated;
    // What a choice evaluates again is the part's own runs: at a point its
    // own search asked for and the other's did not where there is one.
    if (!c->amplitude_indices().empty()) continue;
    CandidateSums* alone[] = {&alone_p, &alone_q};
    for (std::size_t i = 0; i < 2; ++i) {
      const std::vector<bool>& mine = alone[i]->evaluated;
      const std::vector<bool>& other = alone[1 - i]->evaluated;
      int k = -1;
      for (std::size_t j = 0; j < mine.size(); ++j)
        if (mine[j] && (k < 0 || !other[j])) k = static_cast<int>(j);
      ASSERT_GE(k, 0);
      keep_keyed_at(together[i], {k});
      keep_keyed_at(*alone[i], {k});
      const EvaluatedRuns& a = together[i].at[static_cast<std::size_t>(k)];
      const EvaluatedRuns& b = alone[i]->at[static_cast<std::size_t>(k)];
      EXPECT_TRUE(a.keyed.size() > 0 && a.keyed == b.keyed) << c->name << ", set " << i << ", point " << k;
      for (std::size_t r = 0; r < b.sums.size(); ++r)
        EXPECT_TRUE(a.sums[r].z2 == b.sums[r].z2 && a.sums[r].expected == b.sums[r].expected)
            << c->name << ", set " << i << ", point " << k << ", run " << r;
    }
  }
  // Otherwise a part seeing the other's points would go unnoticed.
  EXPECT_TRUE(searches_differ) << "the two sets' searches asked for the same points";
}

}  // namespace
}  // namespace insmc::gap
