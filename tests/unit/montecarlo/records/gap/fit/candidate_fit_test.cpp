// A candidate's grid evaluation (montecarlo/records/gap/fit/candidate_fit.h)
// keeps each grid point's run set and drops the runs' keyed values; the
// points a choice takes are evaluated again (keep_keyed_at). The values
// evaluated again must be those the run set was made from, to the bit, on
// runs of two layouts cut from one lattice.
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

}  // namespace
}  // namespace insmc::gap
