// Coverage of the multi-position calibration's intervals
// (lib/calibration/multiposition.h): over synthetic recordings with known
// errors and white noise, each parameter's 95 % interval misses its true
// value a binomial number of times. Bounds: the binomial(n, 0.05) quantiles
// at a family-wise 0.001 over the 30 parameters, two-sided (too many misses:
// intervals too narrow; too few: too wide). Those bounds cannot see intervals
// that are too wide at 200 recordings (the lower one is 0), so the misses
// are also pooled over the 30 parameters: the recordings are independent,
// so the pooled count's variance is estimated from the per-recording counts
// and the count tested against 5 % of 6000 by the central limit theorem
// (two-sided, 0.001).
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>

#include <boost/math/distributions/binomial.hpp>
#include <boost/math/distributions/normal.hpp>

#include "lib/calibration/multiposition.h"
#include "tests/unit/lib/calibration/multiposition_recording.h"

namespace insmc::testing {
namespace {

TEST(MultipositionCoverage, EachIntervalCoversAtItsStatedRate) {
  constexpr int kRecordings = 200;
  std::mt19937_64 rng(20261126);
  std::map<std::string, int> misses;
  std::vector<double> per_recording;
  for (int r = 0; r < kRecordings; ++r) {
    const SensorErrors e = draw_errors(rng);
    const ImuSamples s = multiposition_recording(e, 20, 6.0, rng);
    const calibration::MultipositionCalibration c = calibration::calibrate_multiposition(s, {});
    ASSERT_TRUE(c.gyro_turns.fitted) << r << ": " << c.gyro_turns.why_not;
    const std::map<std::string, double> truth = truth_of(e);
    int missed = 0;
    for (const auto* f : {&c.accel, &c.gyro_static, &c.gyro_turns})
      for (const auto& p : f->parameters) {
        ASSERT_TRUE(truth.count(p.name)) << p.name;
        const bool miss = !(p.lo_si <= truth.at(p.name) && truth.at(p.name) <= p.hi_si);
        misses[p.name] += miss;
        missed += miss;
      }
    per_recording.push_back(missed);
  }
  double mean = 0, var = 0;
  for (double x : per_recording) mean += x / kRecordings;
  for (double x : per_recording) var += (x - mean) * (x - mean) / (kRecordings - 1);
  const double z = (mean - 0.05 * 30) / std::sqrt(var / kRecordings);
  EXPECT_LE(std::abs(z), boost::math::quantile(boost::math::normal(), 1 - 0.001 / 2))
      << "pooled misses per recording " << mean << " against 1.5";
  ASSERT_EQ(misses.size(), 30u);
  const boost::math::binomial b(kRecordings, 0.05);
  const double tail = 0.001 / 30 / 2;
  const double lo = boost::math::quantile(b, tail), hi = boost::math::quantile(boost::math::complement(b, tail));
  for (const auto& [name, m] : misses) {
    EXPECT_GE(m, lo) << name;
    EXPECT_LE(m, hi) << name;
  }
}

}  // namespace
}  // namespace insmc::testing
