// Round trip of the diagnosis' finding (montecarlo/gap/ranking/finding_check.h,
// fit/subgrid.h): files simulated with an effect at a drawn strength,
// diagnosed blind; the first-ranked finding's 16–84 % range must cover the
// drawn value at its nominal rate, 68 %.
//
// Each file: 20 runs of `insmc simulate`'s own layout with one of four
// effects in turn, its parameter drawn log-uniform over a decade where it is
// detectable: velocity and angle random walk (their 1σ after an hour), a
// Gauss–Markov accelerometer bias instability (its σ, τ at its default 300 s)
// and a thermal transient (its bias at switch-on, the drift and time
// constant at their defaults); its own diagnosis seed. Only the effect's own
// candidate is ranked: what is tested is the interval, not the
// identification (gap-validate's targets). The files are independent, so
// the number covered is binomial(m, 0.68) under the claim (m: files with a
// significant gap and a checked finding); two-sided acceptance region at
// α = 0.01. Power companion, on the same diagnoses: the ranges halved about
// their values must fall below the region (a test that passed with them
// would not see intervals too narrow by two).
#include <gtest/gtest.h>

#include <boost/math/distributions/binomial.hpp>
#include <cmath>
#include <fmt/format.h>
#include <memory>
#include <iterator>
#include <random>
#include <tbb/parallel_for.h>

#include "lib/truth/effect.h"
#include "montecarlo/gap/diagnosis.h"
#include "montecarlo/gap/validation/validation.h"

namespace insmc::mc {
namespace {

constexpr int kFiles = 120;
constexpr std::uint64_t kSeed = 20261128;
constexpr double kNominal = 0.68;  // 16–84 %
constexpr double kAlpha = 0.01;

struct Drawn {
  std::string effect, parameter, unit;
  double low = 0, high = 0;  ///< the decade drawn over, in `unit`
};

const Drawn kDrawn[] = {{"velocity_random_walk", "velocity_1h", "mps", 0.15, 1.5},
                        {"angle_random_walk", "angle_1h", "mrad", 0.1, 1.0},
                        {"accel_bias_instability", "sigma", "ug", 50, 500},
                        {"thermal_transient", "bias", "mg", 0.1, 1.0}};
constexpr int kFamilies = static_cast<int>(std::size(kDrawn));

std::vector<gap::Candidate> only(const std::string& name) {
  for (const gap::Candidate& c : gap::candidate_registry())
    if (c.name == name) return {c};
  throw std::runtime_error("no candidate " + name);
}

TEST(FindingIntervalCoverage, TheFirstRankedRangeCoversTheSimulatedValueAtItsNominalRate) {
  struct File {
    const Drawn* drawn = nullptr;
    EffectSpec spec;
    double truth_si = 0;
    bool checked = false;
    gap::ParameterEstimate estimate;
  };
  std::vector<File> files(kFiles);
  std::mt19937_64 draws(kSeed);  // the engine's sequence is fixed by the standard
  for (int f = 0; f < kFiles; ++f) {
    File& file = files[static_cast<std::size_t>(f)];
    file.drawn = &kDrawn[f % kFamilies];
    const double u = static_cast<double>(draws() >> 11) * 0x1.0p-53;
    const double value = file.drawn->low * std::pow(file.drawn->high / file.drawn->low, u);
    file.spec = parse_effect(fmt::format("{}:{}={:.6g}{}", file.drawn->effect, file.drawn->parameter, value, file.drawn->unit));
    file.truth_si = file.spec.value(file.drawn->parameter);
  }
  tbb::parallel_for(0, kFiles, [&](int f) {
    File& file = files[static_cast<std::size_t>(f)];
    gap::DiagnosisOptions options;
    options.seed = kSeed + 1000 + static_cast<std::uint64_t>(f);
    options.max_selected = 1;
    options.null_shrink_files = 0;
    options.calibration_runs = 100;  // the null only decides which files are significant
    options.bootstrap = 500;
    options.candidates = std::make_shared<const std::vector<gap::Candidate>>(only(file.drawn->effect));
    const gap::Diagnosis g = gap::diagnose(gap::own_layout_file({file.spec}, kSeed + static_cast<std::uint64_t>(f), 20), options);
    if (!g.significant || g.ranking.empty()) return;
    for (const gap::ParameterEstimate& e : g.ranking[0].parameters)
      if (e.name == file.drawn->parameter) {
        file.checked = true;
        file.estimate = e;
      }
  });
  int checked = 0, covered = 0, covered_halved = 0;
  int family_checked[kFamilies] = {}, family_covered[kFamilies] = {};
  for (const File& file : files) {
    if (!file.checked) continue;
    const gap::ParameterEstimate& e = file.estimate;
    ASSERT_TRUE(e.check.measured) << file.drawn->effect;
    ++checked;
    const double t = file.truth_si;
    const auto family = static_cast<std::size_t>(file.drawn - kDrawn);
    ++family_checked[family];
    family_covered[family] += e.low <= t && t <= e.high;
    covered += e.low <= t && t <= e.high;
    covered_halved += e.value - (e.value - e.low) / 2 <= t && t <= e.value + (e.high - e.value) / 2;
  }
  ASSERT_GE(checked, kFiles * 3 / 4) << "the drawn strengths are meant to be detectable";
  const boost::math::binomial claim(checked, kNominal);
  const double lo = boost::math::quantile(claim, kAlpha / 2), hi = boost::math::quantile(boost::math::complement(claim, kAlpha / 2));
  EXPECT_GE(covered, lo) << covered << " of " << checked << " covered";
  EXPECT_LE(covered, hi) << covered << " of " << checked << " covered";
  EXPECT_LT(covered_halved, lo) << "halved ranges: " << covered_halved << " of " << checked;
  std::printf("covered %d of %d (region %.0f-%.0f); halved %d\n", covered, checked, lo, hi, covered_halved);
  // Each family on its own too (its own binomial region): a family far off
  // its rate is not hidden by the others.
  for (int k = 0; k < kFamilies; ++k) {
    const boost::math::binomial family(family_checked[k], kNominal);
    const double family_lo = boost::math::quantile(family, kAlpha / 2);
    const double family_hi = boost::math::quantile(boost::math::complement(family, kAlpha / 2));
    EXPECT_GE(family_covered[k], family_lo) << kDrawn[k].effect;
    EXPECT_LE(family_covered[k], family_hi) << kDrawn[k].effect;
    std::printf("  %s: %d of %d (region %.0f-%.0f)\n", kDrawn[k].effect.c_str(), family_covered[k], family_checked[k],
                family_lo, family_hi);
  }
}

}  // namespace
}  // namespace insmc::mc
