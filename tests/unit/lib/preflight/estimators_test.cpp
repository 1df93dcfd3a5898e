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

}  // namespace
}  // namespace insmc
