// The noise fit on synthetic recordings with known white noise, a
// Gauss–Markov process and a rate random walk (lib/noise/noise_fit.h), for
// a tactical and a navigation-grade gyro, 2 h each, fixed seeds:
// - every term is kept (white, Gauss–Markov and random walk together);
// - each 90 % interval (N, σ, T_c, K) covers its truth a binomial number of
//   times: too few covers (intervals too narrow) fail at a family-wise 0.001;
// - the fit test rejects the true model family no more often than its
//   level α allows (binomial upper bound at 0.001);
// and stationary recordings through the whole stage flag their first hour
// as a warm-up no more often than the stationarity test's level.
#include <gtest/gtest.h>

#include <boost/math/distributions/binomial.hpp>
#include <cmath>
#include <cstdio>
#include <map>
#include <numbers>
#include <string>

#include "lib/noise/noise_analysis.h"
#include "lib/noise/noise_fit.h"
#include "tests/unit/lib/noise/synthetic_noise.h"

namespace insmc::noise {
namespace {

constexpr double kDegph = std::numbers::pi / 180 / 3600;  // deg/h in rad/s
constexpr double kRateHz = 10, kDt = 1 / kRateHz;
constexpr std::size_t kSamples = static_cast<std::size_t>(2 * 3600 * kRateHz);

const TermFit* find(const NoiseFit& f, NoiseTerm t) {
  for (const TermFit& x : f.terms)
    if (x.term == t) return &x;
  return nullptr;
}

struct Grade {
  const char* name;
  test::SyntheticNoise truth;
  std::uint64_t seed;
};

// Tactical: ARW 0.15 deg/√h, a Gauss–Markov bias of 3 deg/h with T_c = 20 s,
// a rate random walk of 8 deg/h/√h. Navigation: ARW 0.003 deg/√h, 0.01 deg/h
// with T_c = 300 s, 0.1 deg/h/√h. Each dominates the Allan deviation over
// about a decade of τ inside 2 h.
const Grade kGrades[] = {
    {"tactical", {.white = 9 * kDegph, .random_walk = 8.0 / 60 * kDegph, .gm_sigma = 3 * kDegph, .gm_time_s = 20}, 1000},
    {"navigation", {.white = 0.18 * kDegph, .random_walk = 0.1 / 60 * kDegph, .gm_sigma = 0.01 * kDegph, .gm_time_s = 300},
     2000}};

TEST(NoiseFitCoverage, EveryTermIsKeptAndItsIntervalCoversAtTheStatedRate) {
  constexpr int kFiles = 12;
  constexpr double kConfidence = 0.9, kAlpha = 0.01;
  int fits = 0, failed_tests = 0;
  std::map<std::string, std::pair<int, int>> cover;  // term → (covered, selected)
  for (const Grade& g : kGrades)
    for (int f = 0; f < kFiles; ++f) {
      const auto y = test::synthetic_series(g.truth, kSamples, kDt, g.seed + static_cast<std::uint64_t>(f));
      const Segment all{0, y.size()};
      NoiseFitOptions o;
      o.confidence = kConfidence;
      o.selection_alpha = kAlpha;
      const NoiseFit fit = fit_noise(overlapping_allan(y, kDt, std::span(&all, 1)), o);
      ++fits;
      failed_tests += !fit.fits || fit.first_level > 0;
      const auto check = [&](const std::string& name, bool selected, double lo, double hi, double truth) {
        auto& [c, s] = cover[std::string(g.name) + " " + name];
        s += selected;
        c += selected && lo <= truth && truth <= hi;
        std::printf("%s %d %s: %s [%.3g, %.3g] truth %.3g\n", g.name, f, name.c_str(), selected ? "kept" : "DROPPED",
                    lo / truth, hi / truth, 1.0);
      };
      const TermFit* n = find(fit, NoiseTerm::kWhiteRate);
      const TermFit* gm = find(fit, NoiseTerm::kGaussMarkov);
      const TermFit* k = find(fit, NoiseTerm::kRateRandomWalk);
      check("white", n, n ? n->lower_si : 0, n ? n->upper_si : 0, g.truth.white);
      check("gauss_markov sigma", gm, gm ? gm->lower_si : 0, gm ? gm->upper_si : 0, g.truth.gm_sigma);
      check("gauss_markov T_c", gm, fit.correlation_time_lower_s, fit.correlation_time_upper_s, g.truth.gm_time_s);
      check("random walk", k, k ? k->lower_si : 0, k ? k->upper_si : 0, g.truth.random_walk);
      std::printf("  fit test J %.1f dof %g p %.3g, first level %zu\n", fit.fit_statistic, fit.fit_dof,
                  fit.fit_p_value, fit.first_level);
    }
  // Every term in every file, and the covers: 8 counts at a family-wise 0.001.
  for (const auto& [name, cs] : cover) {
    const auto [covered, selected] = cs;
    EXPECT_EQ(selected, kFiles) << name;
    EXPECT_GE(covered, boost::math::quantile(boost::math::binomial(selected, kConfidence), 0.001 / 8))
        << name << ": " << covered << " of " << selected;
  }
  // The fit test's false rejections (a fit that fails, or one that passes
  // only without its shortest levels) at most binomial(fits, α).
  EXPECT_LE(failed_tests, boost::math::quantile(boost::math::complement(boost::math::binomial(fits, kAlpha), 0.001)))
      << failed_tests << " of " << fits;
}

TEST(NoiseFitCoverage, StationaryRecordingsRarelyLoseTheirFirstHour) {
  // Three hours at 10 Hz per file, six channels (gyros: white + random walk,
  // accelerometers: white + Gauss–Markov), stationary throughout: each
  // channel's first hour is flagged with probability α (docs/noise.md §5).
  constexpr int kFiles = 4;
  NoiseOptions o;
  o.alpha = 0.05;
  int tested = 0, flagged = 0;
  for (int f = 0; f < kFiles; ++f) {
    SensorRecording r;
    r.dt_s = kDt;
    const std::size_t n = static_cast<std::size_t>(3 * 3600 * kRateHz);
    r.runs = {{0, n}};
    r.run_names = {"stationary"};
    for (std::size_t c = 0; c < kChannels; ++c) {
      const test::SyntheticNoise s = c < 3 ? kGrades[c % 2].truth
                                           : test::SyntheticNoise{.white = 1e-3, .gm_sigma = 2e-4, .gm_time_s = 100};
      r.channel[c] = test::synthetic_series(s, n, kDt, 5000 + 10 * static_cast<std::uint64_t>(f) + c);
    }
    const NoiseAnalysis a = analyse_noise(r, o);
    for (const ChannelNoise& ch : a.channels) {
      tested += ch.stationarity.tested;
      flagged += ch.stationarity.tested && !ch.stationarity.stationary;
      std::printf("%d %s p %.3g\n", f, ch.name.c_str(), ch.stationarity.p_value);
    }
  }
  EXPECT_EQ(tested, kFiles * 6);
  EXPECT_LE(flagged, boost::math::quantile(boost::math::complement(boost::math::binomial(tested, o.alpha), 0.001)))
      << flagged << " of " << tested;
}

}  // namespace
}  // namespace insmc::noise
