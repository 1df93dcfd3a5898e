// The test run's least-squares estimators (4.7)/(4.4) as linear maps: a map
// applied to its own design gives the identity, at the study's interval
// counts and far beyond them (simulate at τ = 0.1 s over 2 h: 72,000), where
// the map is built without a K × K matrix.
#include "lib/preflight/test_run.h"

#include <gtest/gtest.h>

#include <cmath>

namespace insmc {
namespace {

/// max |row j of the map · the data of coefficient j − δ_ij| for the
/// accelerometer fit (4.4) averaged over each interval: Â1 from A1 = 1, etc.
double accel_identity_error(const TestRunEstimators& e, const TestRunOptions& o, const ModelOptions& m) {
  const int K = o.intervals();
  const double w = m.earth_rate_radps, g = m.gravity_mps2;
  double worst = 0;
  for (int j = 0; j < 2; ++j) {  // A1 and U3 (U4 not fitted here)
    for (int i = 0; i < 2; ++i) {
      double sum = 0;
      for (int k = 1; k <= K; ++k) {
        const double t = k * o.filter_interval_s, a = t - o.filter_interval_s;
        const double datum = j == 0 ? g : g * w * (a + t) / 2;
        sum += e.accel(i, k - 1) * datum;
      }
      worst = std::max(worst, std::abs(sum - (i == j ? 1.0 : 0.0)));
    }
  }
  return worst;
}

TEST(Estimators, ReproduceTheirOwnDesignAtAnyIntervalCount) {
  const ModelOptions m;
  for (const auto& [duration_s, interval_s] : {std::pair{900.0, 10.0}, {900.0, 0.5}, {900.0, 0.1}, {7200.0, 0.1}}) {
    TestRunOptions o;
    o.duration_s = duration_s;
    o.filter_interval_s = interval_s;
    const TestRunEstimators e = make_estimators(o, m, true, false);
    ASSERT_EQ(e.accel.cols(), o.intervals());
    // Rounding of K products of unit-norm columns: far below 1e-9.
    EXPECT_LT(accel_identity_error(e, o, m), 1e-9) << duration_s << " s at " << interval_s << " s";
  }
}

/// The design of the position fit (4.7) with the U4 term of (4.5), column j
/// at t_k = kτ.
double position_datum(const ModelOptions& m, int j, double t) {
  const double ws = m.schuler_radps(), x = ws * t, r0 = m.radius_m, q = m.earth_rate_radps / ws;
  const double pos[4] = {std::sin(x) / ws, r0 * (1 - std::cos(x)), r0 * q * (x - std::sin(x)),
                         r0 * q * q * (0.5 * x * x - (1 - std::cos(x)))};
  return pos[j];
}

TEST(Estimators, OverTheIntervalsARunHasTheyAreTheSameFitsWithoutTheMissingOnes) {
  const ModelOptions m;
  TestRunOptions o;  // 15 min at 10 s: K = 90
  const int K = o.intervals();
  ObservedIntervals observed{std::vector<bool>(K, true), std::vector<bool>(K, true)};
  // Every interval given: the same bits as the fits over all of them.
  const TestRunEstimators all = make_estimators(o, m, true, true);
  const TestRunEstimators all_given = make_estimators(o, m, true, true, observed);
  EXPECT_TRUE(all.position == all_given.position && all.accel == all_given.accel);
  // A logger's dropouts, r and f apart, the first and last interval among them.
  for (const int k : {0, 7, 13, 44, 89}) observed.position[static_cast<std::size_t>(k)] = false;
  for (const int k : {0, 21, 60, 61}) observed.accel[static_cast<std::size_t>(k)] = false;
  const TestRunEstimators e = make_estimators(o, m, true, true, observed);
  ASSERT_TRUE(e.fit_u3 && e.fit_u4);
  double worst_position = 0, worst_accel = 0;
  for (int k = 0; k < K; ++k) {
    if (!observed.position[static_cast<std::size_t>(k)]) {
      EXPECT_TRUE((e.position.col(k).array() == 0).all()) << k;
    }
    if (!observed.accel[static_cast<std::size_t>(k)]) {
      EXPECT_TRUE((e.accel.col(k).array() == 0).all()) << k;
    }
  }
  // Each map applied to its own design over the intervals it has: the
  // identity (a least-squares fit reproduces data its model explains).
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      // Relative to the sum's own rounding scale Σ|e d| (the columns span
      // 1/ω_s to r0 q² (ω_s T)²/2).
      double sum = 0, magnitude = 1.0;
      for (int k = 1; k <= K; ++k)
        if (observed.position[static_cast<std::size_t>(k - 1)]) {
          const double term = e.position(i, k - 1) * position_datum(m, j, k * o.filter_interval_s);
          sum += term;
          magnitude += std::abs(term);
        }
      worst_position = std::max(worst_position, std::abs(sum - (i == j ? 1.0 : 0.0)) / magnitude);
    }
  const double w = m.earth_rate_radps, g = m.gravity_mps2;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      double sum = 0;
      for (int k = 1; k <= K; ++k) {
        if (!observed.accel[static_cast<std::size_t>(k - 1)]) continue;
        const double t = k * o.filter_interval_s, a = t - o.filter_interval_s;
        const double datum[3] = {g, g * w * (a + t) / 2, g * w * w * (a * a + a * t + t * t) / 6};
        sum += e.accel(i, k - 1) * datum[j];
      }
      worst_accel = std::max(worst_accel, std::abs(sum - (i == j ? 1.0 : 0.0)));
    }
  EXPECT_LT(worst_position, 1e-9);
  EXPECT_LT(worst_accel, 1e-9);
  // And they differ from the fits over every interval (the test can fail).
  EXPECT_GT((e.position - all.position).cwiseAbs().maxCoeff(), 0.0);
}

}  // namespace
}  // namespace insmc
