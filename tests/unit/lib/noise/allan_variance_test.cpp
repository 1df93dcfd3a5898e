// The overlapping Allan variance against values worked by hand and against
// its chi-square intervals' stated coverage.
#include "lib/noise/allan_variance.h"

#include <boost/math/distributions/binomial.hpp>
#include <gtest/gtest.h>

#include "tests/unit/lib/noise/synthetic_noise.h"

namespace insmc::noise {
namespace {

TEST(AllanVariance, AlternatingSeriesByHand) {
  // y = 1, −1, 1, −1, ... (τ0 = 1 s): θ = 0, 1, 0, 1, ...; every second
  // difference at m = 1 is −2 or 2, so σ²(1 s) = 4/2 = 2; at m = 2 the
  // second differences vanish.
  std::vector<double> y(64);
  for (std::size_t k = 0; k < y.size(); ++k) y[k] = k % 2 ? -1.0 : 1.0;
  const Segment all{0, y.size()};
  const auto levels = overlapping_allan(y, 1.0, std::span(&all, 1));
  ASSERT_GE(levels.size(), 2u);
  EXPECT_DOUBLE_EQ(levels[0].avar, 2.0);
  EXPECT_EQ(levels[0].windows, 63u);
  EXPECT_NEAR(levels[1].avar, 0.0, 1e-24);
}

TEST(AllanVariance, RampIsRSquaredTauSquaredOverTwo) {
  // (C.20): a rate ramp R gives σ²(τ) = R²τ²/2 exactly.
  const double R = 3e-4, dt = 0.5;
  std::vector<double> y(3000);
  for (std::size_t k = 0; k < y.size(); ++k) y[k] = 7.0 + R * static_cast<double>(k) * dt;
  const Segment all{0, y.size()};
  for (const AllanLevel& l : overlapping_allan(y, dt, std::span(&all, 1)))
    EXPECT_NEAR(l.avar, R * R * l.tau_s * l.tau_s / 2, 1e-9 * R * R * l.tau_s * l.tau_s) << l.tau_s;
}

TEST(AllanVariance, NoWindowSpansTwoSegments) {
  // Two segments at different constant levels: a window across the step
  // would see it; within each segment the variance is zero.
  std::vector<double> y(200, 1.0);
  for (std::size_t k = 100; k < 200; ++k) y[k] = 5.0;
  const Segment segs[] = {{0, 100}, {100, 200}};
  for (const AllanLevel& l : overlapping_allan(y, 1.0, segs)) {
    EXPECT_NEAR(l.avar, 0.0, 1e-20);
    EXPECT_EQ(l.segment_samples.size(), 2u);
  }
  const Segment whole{0, 200};
  EXPECT_GT(overlapping_allan(y, 1.0, std::span(&whole, 1))[0].avar, 0.0);
}

TEST(AllanVariance, EdfOfOneWindowIsAtLeastOne) {
  for (PowerLaw t : {PowerLaw::kWhitePhase, PowerLaw::kFlickerPhase, PowerLaw::kWhiteRate, PowerLaw::kFlickerRate,
                     PowerLaw::kRandomWalkRate})
    EXPECT_GE(allan_edf(7, 3, t), 1.0);
  // White rate, m = 1, long series: edf ≈ (3N/2 − 2)·4/9 ≈ 2N/3.
  EXPECT_NEAR(allan_edf(100001, 1, PowerLaw::kWhiteRate) / 100000, 2.0 / 3, 1e-3);
}

TEST(AllanVariance, WhiteNoiseIntervalsCoverAtTheirStatedRate) {
  // 200 white-rate series (N known): per level, the 90 % interval must cover
  // N²/τ in a fraction of files consistent with 0.90 (two-sided binomial
  // test at 0.1 % per level).
  const double N = 2e-3, dt = 0.01, confidence = 0.90;
  const int files = 200;
  std::vector<int> covered;
  std::vector<double> taus;
  for (int f = 0; f < files; ++f) {
    const auto y = test::synthetic_series({.white = N}, 8192, dt, 1000 + static_cast<std::uint64_t>(f));
    const Segment all{0, y.size()};
    const auto levels = overlapping_allan(y, dt, std::span(&all, 1));
    covered.resize(levels.size());
    taus.resize(levels.size());
    for (std::size_t j = 0; j < levels.size(); ++j) {
      const auto ci = adev_interval(levels[j].avar, allan_edf(levels[j], PowerLaw::kWhiteRate), confidence);
      const double truth = N / std::sqrt(levels[j].tau_s);
      covered[j] += ci.lo <= truth && truth <= ci.hi;
      taus[j] = levels[j].tau_s;
    }
  }
  const boost::math::binomial b(files, confidence);
  const double lo = boost::math::quantile(b, 0.0005), hi = boost::math::quantile(boost::math::complement(b, 0.0005));
  for (std::size_t j = 0; j < covered.size(); ++j) {
    EXPECT_GE(covered[j], lo) << "tau " << taus[j];
    EXPECT_LE(covered[j], hi) << "tau " << taus[j];
  }
}

}  // namespace
}  // namespace insmc::noise
