// The noise-term fit on synthetic series with known terms: the right terms
// are selected and the profile intervals cover the truth at their stated
// rate (binomial test over the files).
#include "lib/noise/noise_fit.h"

#include <boost/math/distributions/binomial.hpp>
#include <cmath>
#include <cstdio>
#include <gtest/gtest.h>

#include "tests/unit/lib/noise/synthetic_noise.h"

namespace insmc::noise {
namespace {

const TermFit* find(const NoiseFit& f, NoiseTerm t) {
  for (const TermFit& x : f.terms)
    if (x.term == t) return &x;
  return nullptr;
}

NoiseFit fit_series(const test::SyntheticNoise& s, std::size_t n, double dt, std::uint64_t seed, double confidence) {
  const auto y = test::synthetic_series(s, n, dt, seed);
  const Segment all{0, y.size()};
  NoiseFitOptions o;
  o.confidence = confidence;
  return fit_noise(overlapping_allan(y, dt, std::span(&all, 1)), o);
}

TEST(NoiseFit, WhiteAndRandomWalkRecoveredWithCoverage) {
  // White rate and a rate random walk that dominates the Allan variance from
  // τ ≈ 20 s on, 100 Hz, 2^18 samples (44 min). (A walk that shows only in
  // the last two or three levels is a 2–3σ effect there and is rightly not
  // always selected.)
  const test::SyntheticNoise truth{.white = 3e-5, .random_walk = 4e-6};
  const int files = 60;
  const double confidence = 0.90;
  int white_cov = 0, walk_cov = 0, white_sel = 0, walk_sel = 0, gm_instead = 0, other_terms = 0;
  for (int f = 0; f < files; ++f) {
    const NoiseFit fit = fit_series(truth, 1 << 18, 0.01, 77 + static_cast<std::uint64_t>(f), confidence);
    if (const TermFit* w = find(fit, NoiseTerm::kWhiteRate)) {
      ++white_sel;
      white_cov += w->lower_si <= truth.white && truth.white <= w->upper_si;
    }
    if (const TermFit* k = find(fit, NoiseTerm::kRateRandomWalk)) {
      ++walk_sel;
      walk_cov += k->lower_si <= truth.random_walk && truth.random_walk <= k->upper_si;
    }
    gm_instead += find(fit, NoiseTerm::kGaussMarkov) != nullptr && find(fit, NoiseTerm::kRateRandomWalk) == nullptr;
    other_terms += find(fit, NoiseTerm::kQuantization) != nullptr;
    other_terms += find(fit, NoiseTerm::kBiasInstability) != nullptr;
    other_terms += find(fit, NoiseTerm::kRateRamp) != nullptr;
  }
  EXPECT_EQ(white_sel, files);
  // The walk is found in every file, as a rate random walk or, less often, as
  // a Gauss–Markov process with T_c inside the record (over 44 min one
  // realization of a walk can bend like one; the choice between them is a
  // maximum over T_c, so it happens more often than α; docs/noise.md §3).
  EXPECT_EQ(walk_sel + gm_instead, files);
  EXPECT_GE(walk_sel, files / 2);
  const boost::math::binomial b(files, confidence);
  const double lo = boost::math::quantile(b, 0.001);
  EXPECT_GE(white_cov, lo);
  EXPECT_GE(walk_cov, boost::math::quantile(boost::math::binomial(walk_sel, confidence), 0.001));
  // Spurious terms: each of the three others is kept with probability about
  // 2α (0.02, the one-sided boundary test) per file.
  EXPECT_LE(other_terms, boost::math::quantile(boost::math::complement(boost::math::binomial(3 * files, 0.02), 0.001)));
}

TEST(NoiseFit, GaussMarkovCorrelationTimeCoverage) {
  const test::SyntheticNoise truth{.white = 1e-4, .gm_sigma = 2e-4, .gm_time_s = 50};
  const int files = 20;
  const double confidence = 0.9;
  int selected = 0, tc_cov = 0, sigma_cov = 0;
  for (int f = 0; f < files; ++f) {
    const NoiseFit fit = fit_series(truth, 1 << 18, 0.01, 500 + static_cast<std::uint64_t>(f), confidence);
    const TermFit* gm = find(fit, NoiseTerm::kGaussMarkov);
    if (!gm) continue;
    ++selected;
    tc_cov += fit.correlation_time_lower_s <= 50.0 && 50.0 <= fit.correlation_time_upper_s;
    sigma_cov += gm->lower_si <= 2e-4 && 2e-4 <= gm->upper_si;
  }
  EXPECT_GE(selected, files - 1);
  const double lo = boost::math::quantile(boost::math::binomial(selected, confidence), 0.001);
  EXPECT_GE(tc_cov, lo);
  EXPECT_GE(sigma_cov, lo);
}

TEST(NoiseFit, WhiteGaussMarkovAndRandomWalkAreKeptTogether) {
  // A tactical gyro, 2 h at 10 Hz: white noise 9 deg/h/√Hz, a Gauss–Markov
  // process of 3 deg/h with T_c = 20 s and a rate random walk of
  // 8 deg/h/√h, each dominating a decade of τ (the Gauss–Markov hump is
  // more than 10 standard deviations of its levels above the white line).
  // A model without the walk passed a fit test weighted by a pilot that had
  // it, and failed its own (J in the thousands); the selection now judges
  // every simpler model by its own covariance. Measured on these 20 files:
  // before, the three kept together in 8; now in 14, with the walk taken as a
  // ramp in 5 more (over 2 h one realization of a walk can bend like one).
  constexpr double kDegph = 3.14159265358979323846 / 180 / 3600;  // rad/s
  const test::SyntheticNoise truth{.white = 9 * kDegph, .random_walk = 8 * kDegph / 60, .gm_sigma = 3 * kDegph,
                                   .gm_time_s = 20};
  const int files = 20;
  const double confidence = 0.9;
  int white_kept = 0, gm_kept = 0, rise_kept = 0, together = 0;
  int covered[4] = {};  // N, σ, K, T_c
  for (int f = 0; f < files; ++f) {
    const NoiseFit fit = fit_series(truth, 72000, 0.1, 1000 + static_cast<std::uint64_t>(f), confidence);
    const TermFit* w = find(fit, NoiseTerm::kWhiteRate);
    const TermFit* g = find(fit, NoiseTerm::kGaussMarkov);
    const TermFit* k = find(fit, NoiseTerm::kRateRandomWalk);
    white_kept += w != nullptr;
    gm_kept += g != nullptr;
    rise_kept += k != nullptr || find(fit, NoiseTerm::kRateRamp) != nullptr;
    if (!w || !g || !k) continue;
    ++together;
    covered[0] += w->lower_si <= truth.white && truth.white <= w->upper_si;
    covered[1] += g->lower_si <= truth.gm_sigma && truth.gm_sigma <= g->upper_si;
    covered[2] += k->lower_si <= truth.random_walk && truth.random_walk <= k->upper_si;
    covered[3] += fit.correlation_time_lower_s <= truth.gm_time_s && truth.gm_time_s <= fit.correlation_time_upper_s;
  }
  EXPECT_EQ(white_kept, files);
  // The hump and the long-τ rise are each many standard deviations out: a
  // file that loses either is a selection failure, allowed once or twice.
  EXPECT_GE(gm_kept, files - 2);
  EXPECT_GE(rise_kept, files - 2);
  EXPECT_GE(together, files / 2);
  // Each interval at its stated rate where the three are kept: per term the
  // files are independent, so its count is binomial(together, 0.9); the
  // 0.001 quantile of each.
  const double lo = boost::math::quantile(boost::math::binomial(together, confidence), 0.001);
  for (int t = 0; t < 4; ++t) EXPECT_GE(covered[t], lo) << "interval " << t << " (N, σ, K, T_c)";
}

TEST(NoiseFit, NavigationGradeWhiteNoiseAndRandomWalkCoverAtTheirRate) {
  // A navigation-grade gyro, 2 h at 10 Hz: white noise 0.18 deg/h/√Hz
  // (0.003 deg/√h), a rate random walk of 0.1 deg/h/√h and a Gauss–Markov
  // bias of 0.01 deg/h over 300 s (the grade of
  // tests/statistical/noise_warmup_false_alarm_test.cpp). The white noise and
  // the walk each dominate decades of τ and must be kept and cover; the
  // Gauss–Markov term is at its peak 6 % of the Allan variance under the walk
  // while a level's estimate there scatters about 30 %, so 2 h cannot show it
  // and it is not asked for (docs/noise.md §7).
  constexpr double kDegph = 3.14159265358979323846 / 180 / 3600;  // rad/s
  const test::SyntheticNoise truth{.white = 0.18 * kDegph, .random_walk = 0.1 / 60 * kDegph,
                                   .gm_sigma = 0.01 * kDegph, .gm_time_s = 300};
  const int files = 12;
  const double confidence = 0.9;
  int white_kept = 0, walk_kept = 0, white_cov = 0, walk_cov = 0;
  for (int f = 0; f < files; ++f) {
    const NoiseFit fit = fit_series(truth, 72000, 0.1, 5000 + static_cast<std::uint64_t>(f), confidence);
    if (const TermFit* w = find(fit, NoiseTerm::kWhiteRate)) {
      ++white_kept;
      white_cov += w->lower_si <= truth.white && truth.white <= w->upper_si;
    }
    if (const TermFit* k = find(fit, NoiseTerm::kRateRandomWalk)) {
      ++walk_kept;
      walk_cov += k->lower_si <= truth.random_walk && truth.random_walk <= k->upper_si;
    }
  }
  EXPECT_EQ(white_kept, files);
  EXPECT_GE(walk_kept, files - 1);
  EXPECT_GE(white_cov, boost::math::quantile(boost::math::binomial(white_kept, confidence), 0.001)) << white_cov;
  EXPECT_GE(walk_cov, boost::math::quantile(boost::math::binomial(walk_kept, confidence), 0.001)) << walk_cov;
  std::printf("navigation grade, %d files: white kept %d covering %d, walk kept %d covering %d\n", files, white_kept,
              white_cov, walk_kept, walk_cov);
}

TEST(NoiseFit, ARecordingNoModelFitsIsReportedAsSuchNotAnError) {
  // A pattern of 23 samples repeated (a logger replaying its buffer): its
  // Allan variance falls as τ⁻² beyond the period, like no standard term.
  // The selection could end on a model with no degree of freedom left or a
  // singular covariance, and the fit test's chi-square of a NaN statistic
  // threw (an internal error of `insmc noise` and `import-imu`).
  std::vector<double> y(59999);
  for (std::size_t k = 0; k < y.size(); ++k) y[k] = 1e-6 * static_cast<double>((7 * k) % 23);
  const Segment all{0, y.size()};
  NoiseFit fit;
  ASSERT_NO_THROW(fit = fit_noise(overlapping_allan(y, 0.01, std::span(&all, 1))));
  EXPECT_FALSE(fit.fits);
  EXPECT_TRUE(std::isfinite(fit.fit_p_value));
  EXPECT_GE(fit.fit_dof, 1.0);
}

TEST(NoiseFit, QuantizationAndRamp) {
  const test::SyntheticNoise truth{.quantization = 1e-4, .white = 2e-5, .ramp = 1e-8};
  const NoiseFit fit = fit_series(truth, 1 << 18, 0.01, 11, 0.99);
  for (auto [term, value] : {std::pair{NoiseTerm::kQuantization, 1e-4}, std::pair{NoiseTerm::kRateRamp, 1e-8}}) {
    const TermFit* t = find(fit, term);
    ASSERT_NE(t, nullptr) << term_name(term, SensorKind::kGyro);
    EXPECT_LE(t->lower_si, value);
    EXPECT_GE(t->upper_si, value);
  }
}

}  // namespace
}  // namespace insmc::noise
