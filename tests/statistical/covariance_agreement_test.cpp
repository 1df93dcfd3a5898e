// Statistical test: the Monte Carlo RMS² of every output agrees with the
// exact linear covariance (the central test: fixed seeds, bounds derived from
// the distribution).
//
// Statistic: for each output (system 1 and 2 × report times 42/63/84 min ×
// axes x, y, z, horizontal), the Monte Carlo mean of r² over n = 1e5
// samples, m̂2 = Σr²/n, compared with the exact E[r²] = mean² + sᵀ P s of the
// study's linear map (StudyMap::predicted_rms). For the horizontal output
// r² = N² + E² is a quadratic form of the same x.
// Sampling distribution: the samples are i.i.d., so by the central limit
// theorem m̂2 ~ N(E[r²], Var(r²)/n), with Var(r²) computed exactly from the
// same map and the exact second and fourth moments of each x_j
// (StudyMap::predicted_var_r2). The bound |m̂2 − E r²| ≤ z·sqrt(Var(r²)/n)
// contains no estimated quantity.
// Also, for the case with fixed (nonzero-mean) parameters, the Monte Carlo
// mean of r on the x, y, z axes against the exact E[r] = sᵀμ, with
// Var(r) = E[r²] − E[r]² exactly.
// α: family-wise 1e-6 for this file, split equally (Bonferroni) over all
// kAssertions checks, so each check is a two-sided interval at level
// 1 − 1e-6/90 (z = 5.7), far stricter than 99.9% per check (asserted below).
// CLT accuracy: r² has skewness at most about 2.8 (that of χ²₁, r normal),
// so m̂2's is below 0.01 at n = 1e5. Its Edgeworth term moves each tail at
// z = 5.7 by about ±30% but cancels in the two-sided rate; the remaining
// terms are O(1/n), a few percent here. The false-alarm rate is 1e-6 to
// within that.
// Power companions: (1) gyro_drift bounds × 1.1 on the Monte Carlo side
// only: every output whose E[r²] is at least half gyro_drift must then fail
// the same check; (2) the fixed accel_bias_z value × 1.1 on the Monte Carlo
// side: the mean check must fail for the outputs where this is detectable.
// In both the power is computed from the exact moments of the perturbed
// study (normal approximation) and must be ≥ 0.999 for every output relied
// on, and the sum of their misses ≤ 1e-3.
#include <gtest/gtest.h>

#include <algorithm>
#include <boost/math/distributions/normal.hpp>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <string>
#include <vector>

#include "lib/compensation/scheme.h"
#include "lib/uncertainty/catalogue.h"
#include "montecarlo/study/engine/engine.h"
#include "tests/statistical/r2_check.h"

namespace insmc::mc {
namespace {

constexpr double kFamilyAlpha = 1e-6;
constexpr std::uint64_t kSamples = 100000;
constexpr int kOutputsPerStudy = 2 * 3 * 4;  // systems × report times × axes
constexpr int kStudies = 3;                   // paper, linear, linear with normal:3 and fixed values
constexpr int kMeanChecks = 2 * 3 * 3;        // the x, y, z outputs of the third study
constexpr int kAssertions = kStudies * kOutputsPerStudy + kMeanChecks;
constexpr double kAlphaPerCheck = kFamilyAlpha / kAssertions;
static_assert(kAlphaPerCheck <= 1e-3, "every check must be a 99.9% or stricter interval");
constexpr double kPowerRequired = 0.999;

const double kZ = boost::math::quantile(boost::math::complement(boost::math::normal(), kAlphaPerCheck / 2));

// Layout and map built once per config (StudyMap keeps pointers to both).
struct Study {
  explicit Study(const StudyConfig& config) : c(config), layout(make_layout(c)), map(c, layout) {}
  StudyConfig c;
  StudyLayout layout;
  StudyMap map;
};

// Scheme none: the position error is then exactly linear in x, so the
// predicted moments are exact. (The compensation schemes add quantized
// measurements whose prediction uses an additive-noise model.)
StudyConfig base_config(Fidelity fidelity, std::uint64_t seed) {
  StudyConfig c;
  c.schemes = {Scheme::kNone};
  c.fidelity = fidelity;
  c.with_grid = false;  // the report times 42/63/84 min only
  c.samples = kSamples;
  c.seed = seed;
  c.threads = 2;
  return c;
}

// The --dist normal:3 study with three fixed (nonzero-mean) parameters.
StudyConfig mixed_config(std::uint64_t seed) {
  StudyConfig c = base_config(Fidelity::kLinear, seed);
  c.uncertainties.apply_dist("all=normal:3");
  c.uncertainties.apply_dist("accel_bias_z=fixed:1mg");
  c.uncertainties.apply_dist("gyro_drift_y=fixed:-5meru");
  c.uncertainties.apply_dist("theodolite_azimuth=fixed:0.5mrad");
  return c;
}


using testing::describe;
using testing::R2Check;
R2Check r2_check(const OutputStats& s, const StudyMap& exact, std::size_t o) {
  return testing::r2_check(s, exact, o, kZ);
}

double two_sided_power(double shift, double sd_null, double sd_alt) {
  return testing::two_sided_power(shift, sd_null, sd_alt, kZ);
}

StudyAccumulator run(const Study& st) { return run_blocks(st.c, st.map, 0, block_count(st.c.samples)); }

void expect_rms2_agrees(const Study& st, const StudyAccumulator& acc) {
  ASSERT_EQ(st.layout.outputs.size(), static_cast<std::size_t>(kOutputsPerStudy));
  double largest = 0;  // the largest |standardized deviation|, for the log
  for (std::size_t o = 0; o < st.layout.outputs.size(); ++o) {
    ASSERT_GT(st.map.predicted_var_r2()[o], 0.0) << describe(st.layout, o);
    ASSERT_EQ(acc.outputs()[o].count(), kSamples);
    const R2Check c = r2_check(acc.outputs()[o], st.map, o);
    largest = std::max(largest, std::fabs(c.deviation / c.bound * kZ));
    EXPECT_TRUE(c.pass()) << describe(st.layout, o) << ": mean r² − E r² = " << c.deviation << " m², bound ±"
                          << c.bound << " (z = " << c.deviation / c.bound * kZ << ")";
  }
  std::cout << "largest |z| " << largest << " of " << kOutputsPerStudy << " outputs (accept <= " << kZ << ")\n";
}

TEST(CovarianceAgreement, PaperFidelity) {
  std::cout << "z = " << kZ << " per check (alpha " << kAlphaPerCheck << ")\n";
  const Study st(base_config(Fidelity::kPaper, 1001));
  expect_rms2_agrees(st, run(st));
}

TEST(CovarianceAgreement, LinearFidelity) {
  const Study st(base_config(Fidelity::kLinear, 1002));
  expect_rms2_agrees(st, run(st));
}

TEST(CovarianceAgreement, NormalDrawsWithFixedValues) {
  const Study st(mixed_config(1003));
  const StudyAccumulator acc = run(st);
  expect_rms2_agrees(st, acc);
  // The mean of r on the x, y, z axes against E[r] = sᵀμ: the fixed values
  // make it nonzero (the OutputStats shift is exercised with a real offset).
  int mean_checks = 0, nonzero_means = 0;
  for (std::size_t o = 0; o < st.layout.outputs.size(); ++o) {
    if (st.layout.outputs[o].axis == Axis::kHorizontal) continue;
    ++mean_checks;
    const double mean = st.map.predicted_mean()[o], rms = st.map.predicted_rms()[o];
    const double sd = std::sqrt((rms * rms - mean * mean) / static_cast<double>(kSamples));
    if (std::fabs(mean) > 10 * sd) ++nonzero_means;
    const OutputSummary s = acc.outputs()[o].summarize(st.c.confidence);
    EXPECT_LE(std::fabs(s.mean - mean), kZ * sd)
        << describe(st.layout, o) << ": mean r " << s.mean << " m vs exact " << mean << " m, bound ±" << kZ * sd;
  }
  EXPECT_EQ(mean_checks, kMeanChecks);
  EXPECT_GE(nonzero_means, 6) << "the fixed values should give clearly nonzero means";
}

// ---------------------------------------------------------------- power companions

TEST(CovarianceAgreementPower, TenPercentWiderGyroDriftFails) {
  const Study null_study(base_config(Fidelity::kLinear, 1004));
  StudyConfig wider = base_config(Fidelity::kLinear, 1004);
  for (const int j : select_uncertainties("gyro_drift")) wider.uncertainties.at(j).bound_si *= 1.1;
  const Study mc(wider);  // the Monte Carlo side, and the alternative's exact moments
  // budget_shares(): the first uncertainty_slot::kDim sources are the catalogue parameters.
  const std::vector<std::vector<double>> shares = null_study.map.budget_shares();
  const double n = static_cast<double>(kSamples);
  std::vector<std::size_t> dominated;
  double total_miss = 0;
  for (std::size_t o = 0; o < null_study.layout.outputs.size(); ++o) {
    double share = 0;
    for (const int j : select_uncertainties("gyro_drift")) share += shares[o][static_cast<std::size_t>(j)];
    if (share < 0.5) continue;
    dominated.push_back(o);
    const double e0 = std::pow(null_study.map.predicted_rms()[o], 2), e1 = std::pow(mc.map.predicted_rms()[o], 2);
    const double power = two_sided_power(e1 - e0, std::sqrt(null_study.map.predicted_var_r2()[o] / n),
                                         std::sqrt(mc.map.predicted_var_r2()[o] / n));
    ASSERT_GE(power, kPowerRequired) << describe(null_study.layout, o);
    total_miss += 1 - power;
  }
  std::cout << dominated.size() << " outputs with gyro_drift share >= 0.5\n";
  ASSERT_GE(dominated.size(), 12u) << "gyro_drift should dominate most outputs at 63 and 84 min";
  ASSERT_LE(total_miss, 1 - kPowerRequired);
  const StudyAccumulator acc = run(mc);
  for (const std::size_t o : dominated) {
    const R2Check c = r2_check(acc.outputs()[o], null_study.map, o);
    EXPECT_FALSE(c.pass()) << describe(null_study.layout, o)
                           << ": the check cannot see gyro_drift bounds 10% too wide (deviation " << c.deviation
                           << ", bound " << c.bound << ")";
  }
}

TEST(CovarianceAgreementPower, TenPercentLargerFixedValueFailsTheMeanCheck) {
  const Study null_study(mixed_config(1005));
  StudyConfig shifted = mixed_config(1005);
  ParameterDistribution& p = shifted.uncertainties.at(uncertainty_slot::kAccelBias + 2);
  ASSERT_EQ(p.kind, DistributionKind::kFixed);
  p.fixed_si *= 1.1;
  const Study mc(shifted);
  const double n = static_cast<double>(kSamples);
  std::vector<std::size_t> detectable;
  double total_miss = 0;
  for (std::size_t o = 0; o < null_study.layout.outputs.size(); ++o) {
    if (null_study.layout.outputs[o].axis == Axis::kHorizontal) continue;
    const double m0 = null_study.map.predicted_mean()[o], m1 = mc.map.predicted_mean()[o];
    const double rms = null_study.map.predicted_rms()[o];
    const double sd = std::sqrt((rms * rms - m0 * m0) / n);  // a fixed value adds no variance
    const double power = two_sided_power(m1 - m0, sd, sd);
    if (power < kPowerRequired) continue;
    detectable.push_back(o);
    total_miss += 1 - power;
  }
  // accel_bias_z drives the z outputs at 42 and 63 min of both systems (at
  // 84 min its mean contribution is small): these four must be detectable.
  int z_outputs = 0;
  for (const std::size_t o : detectable) {
    z_outputs += null_study.layout.outputs[o].axis == Axis::kZ;
    std::cout << "relied on: " << describe(null_study.layout, o) << "\n";
  }
  ASSERT_GE(z_outputs, 4);
  ASSERT_LE(total_miss, 1 - kPowerRequired);
  const StudyAccumulator acc = run(mc);
  for (const std::size_t o : detectable) {
    const double m0 = null_study.map.predicted_mean()[o], rms = null_study.map.predicted_rms()[o];
    const double sd = std::sqrt((rms * rms - m0 * m0) / n);
    const double mean = acc.outputs()[o].summarize(mc.c.confidence).mean;
    EXPECT_GT(std::fabs(mean - m0), kZ * sd)
        << describe(null_study.layout, o) << ": the mean check cannot see a 10% larger fixed accel_bias_z";
  }
}

}  // namespace
}  // namespace insmc::mc
