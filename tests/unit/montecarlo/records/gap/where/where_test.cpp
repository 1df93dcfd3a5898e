// Where the gap lies: the post-test innovations on the error's time
// functions, and the shares summed by a key.
#include "montecarlo/records/gap/where/where.h"

#include <gtest/gtest.h>

#include <cmath>

#include "tests/unit/montecarlo/records/runs/test_layout.h"

namespace insmc::gap {
namespace {

/// Each run's rows: `r_of(t)` on the post-test r rows of `axis`, 0 elsewhere.
template <class F>
Eigen::VectorXd rows_with(const runs::Layout& l, int axis, const F& r_of) {
  Eigen::VectorXd z = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(l.rows.size()));
  for (std::size_t i = static_cast<std::size_t>(l.test_rows); i < l.rows.size(); ++i)
    if (l.rows[i].quantity == runs::Quantity::kR && l.rows[i].axis == axis)
      z[static_cast<Eigen::Index>(i)] = r_of(l.rows[i].t_s);
  return z;
}

double share_named(const TimeFunctionShares& s, const std::string& prefix) {
  for (const Share& x : s.shares)
    if (x.name.rfind(prefix, 0) == 0) return x.share;
  ADD_FAILURE() << "no share " << prefix;
  return -1;
}

TEST(WhereTimeFunctions, ASchulerOscillationIsTheSchulerTermsOnItsAxisAlone) {
  const runs::Layout l = runs::testing::test_layout(3 * 5400.0);
  const runs::RecordSite site = runs::testing::test_site();
  const double ws = site.model.schuler_radps();
  const std::vector<const runs::Layout*> layouts = {&l, &l};
  const std::vector<Eigen::VectorXd> z = {rows_with(l, 1, [&](double t) { return 3.0 * std::sin(ws * t + 0.4); }),
                                          rows_with(l, 1, [&](double t) { return -2.0 * std::cos(ws * t); })};
  const std::vector<TimeFunctionShares> shares = time_function_shares(layouts, z, site);
  ASSERT_EQ(shares.size(), 3u);
  // Exact up to rounding: the data lie in the span of sin and cos ω_s t.
  EXPECT_NEAR(share_named(shares[1], "Schuler"), 1.0, 1e-12);
  EXPECT_NEAR(share_named(shares[1], "rest"), 0.0, 1e-12);
  EXPECT_TRUE(shares[0].shares.empty());  // no energy on x: nothing to share
  EXPECT_TRUE(shares[2].shares.empty());
}

TEST(WhereTimeFunctions, EachTermTakesWhatIsLeftSoTheSharesAreAPartitionOfTheEnergy) {
  // Each term is fitted to what the terms before it left (least squares:
  // the fit and its residual are orthogonal), so the shares are
  // nonnegative and add up to one with the rest, whatever the signal.
  const runs::Layout l = runs::testing::test_layout(2 * 5400.0);
  const runs::RecordSite site = runs::testing::test_site();
  const double end = l.rows.back().t_s, wie = site.model.earth_rate_radps;
  const std::vector<const runs::Layout*> layouts = {&l};
  const std::vector<Eigen::VectorXd> z = {
      rows_with(l, 2, [&](double t) { return std::pow(t / end, 2) + 0.3 * std::sin(wie * t) + 0.1 * std::cos(7e-3 * t); })};
  const TimeFunctionShares s = time_function_shares(layouts, z, site)[2];
  ASSERT_EQ(s.shares.size(), 6u);
  double sum = 0;
  for (const Share& x : s.shares) {
    EXPECT_GE(x.share, 0.0) << x.name;
    sum += x.share;
  }
  EXPECT_NEAR(sum, 1.0, 1e-12);
  EXPECT_GT(share_named(s, "t^2"), 0.0);
  EXPECT_GT(share_named(s, "rest"), 0.0);  // the 15-min wave is none of the terms
}

TEST(WhereShares, SumTheGroupsSharesUnderEachKeyInOrderOfFirstAppearance) {
  std::vector<GroupResult> groups(4);
  groups[0].group = 0, groups[0].share = 0.1;
  groups[1].group = 1, groups[1].share = 0.2;
  groups[2].group = 2, groups[2].share = 0.3;
  groups[3].group = 3, groups[3].share = 0.4;
  const std::vector<Share> by_parity = shares_by(groups, [](const GroupResult& g) { return g.group % 2 ? "odd" : "even"; });
  ASSERT_EQ(by_parity.size(), 2u);
  EXPECT_EQ(by_parity[0].name, "even");
  EXPECT_DOUBLE_EQ(by_parity[0].share, 0.1 + 0.3);
  EXPECT_EQ(by_parity[1].name, "odd");
  EXPECT_DOUBLE_EQ(by_parity[1].share, 0.2 + 0.4);
}

}  // namespace
}  // namespace insmc::gap
