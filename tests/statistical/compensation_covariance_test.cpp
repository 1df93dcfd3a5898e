// Statistical test: with continuous outputs the Monte Carlo RMS² of every
// compensation scheme agrees with the linear-covariance prediction
// (fixed seeds, bounds derived from the distribution), and with the ΔV
// pulses and the position resolution on, the Monte Carlo–covariance
// difference is measured and printed.
//
// Part 1, the check. Studies with --dv-pulse 0, position resolution 0,
// torquer pulse 0 (5.4's command counter) and sway off, for each fidelity
// (paper, linear): every scheme (none, 5.1.1, 5.1.2, combined, 5.2, 5.3,
// 5.4) × system 1, 2 × 42/63/84 min × x, y, z, horizontal = 168 outputs.
// The test-run fits and alignment-phase measurements then see exact data,
// so the extended vector is exactly z = G w with w the independent
// uncertainties and fresh realignment draws (system_pipeline.h), and every
// output is a linear (x, y, z) or quadratic (horizontal, N² + E²) form in w:
// StudyMap gives E[r²] and Var(r²) exactly from the second and fourth
// moments of each w_j.
// Statistic: m̂2 = Σr²/n over n = 20,000 i.i.d. samples, per output.
// Sampling distribution: by the central limit theorem
// m̂2 ~ N(E[r²], Var(r²)/n); the bound |m̂2 − E r²| ≤ z sqrt(Var(r²)/n)
// contains no estimated quantity.
// α: family-wise 1e-6 for this file, split equally (Bonferroni) over the
// 2 × 168 checks: each is a two-sided interval at 1 − 1e-6/336 (z = 5.9).
// CLT accuracy: r² has skewness at most that of χ²₁ (2.8, r normal; the
// uniform draws give lighter tails), so m̂2's is below 0.02 at n = 20,000.
// The Edgeworth term moves each tail at z = 5.9 by a fraction
// skew·z³/6 ≈ 0.7 of itself but cancels in the two-sided rate; what
// remains is O(1/n). The false-alarm rate is 1e-6 up to a factor of order 1
// at worst, which the power companion and the ≥ 0.999 per-check level keep
// honest.
// Power companion: the Table 3.1 gyro-drift bound (the gyro_drift group,
// 10 meru) × 1.1 on the Monte Carlo side only, linear fidelity. The outputs
// relied on are those whose power — computed from the exact moments of the
// perturbed study, normal approximation — is ≥ 0.999; every scheme must have
// at least one, the sum of their misses must be ≤ 1e-3, and each must fail
// the same check.
//
// Part 2, the measurement (no statistical claim). The report's measurement
// model on: ΔV pulses of 0.1 ft/s, position resolution 3 ft, torquer pulses
// of 1 arcsec. The covariance (StudyMap) treats them as additive noise:
//  * ΔV pulses: each counter reading is the counted velocity
//    v_k + φ − U_k, with the phase φ at switch-over and the carried
//    remainder U_k taken as independent uniforms on [0, ΔV) per count, so
//    the filter box's Δf_k gets (U_{k−1} − U_k)/τ (one pulse of uniform
//    rounding per count, differenced);
//  * position resolution: dithered rounding, e_k independent uniform on
//    [−q/2, q/2] per reading (the difference to the reading at switch-over);
//  * torquer and alignment ΔV counters of 5.4: (φ − U)/t_avg likewise.
// The Monte Carlo floors the actual counted signal, so its remainders are
// deterministic functions of the signal (correlated from count to count
// where the signal moves by less than a pulse per interval). The relative
// difference (RMS_MC − RMS_cov)/RMS_cov per scheme × system × time
// (horizontal, n = 10,000) is printed with its ± z half-width, and so is the
// paired measurement of the noise's own contribution (2,000 pairs, see
// measure_pulse_effect); only sanity is asserted (|difference| <
// kSanityFraction).
#include <fmt/format.h>
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
#include "montecarlo/study/sampler/sampler.h"

namespace insmc::mc {
namespace {

constexpr double kFamilyAlpha = 1e-6;
// Debug + ASan in CI runs five studies of this size in reasonable time.
constexpr std::uint64_t kSamples = 20000;
constexpr int kSchemes = 7, kSystems = 2, kTimes = 3, kAxes = 4;
constexpr int kOutputsPerStudy = kSchemes * kSystems * kTimes * kAxes;
constexpr int kStudies = 2;  // paper, linear
constexpr int kAssertions = kStudies * kOutputsPerStudy;
constexpr double kAlphaPerCheck = kFamilyAlpha / kAssertions;
static_assert(kAlphaPerCheck <= 1e-3, "every check must be a 99.9% or stricter interval");
constexpr double kPowerRequired = 0.999;
constexpr double kBoundFactor = 1.1;  // the power companion's wider bound
// Part 2: a measured quantity, asserted only against a gross failure of the
// additive-noise model (the pulse and rounding effects are a few percent of
// the RMS at most, see the printout).
constexpr double kSanityFraction = 0.25;

const double kZ = boost::math::quantile(boost::math::complement(boost::math::normal(), kAlphaPerCheck / 2));

struct Study {
  explicit Study(const StudyConfig& config) : c(config), layout(make_layout(c)), map(c, layout) {}
  StudyConfig c;
  StudyLayout layout;
  StudyMap map;
};

StudyConfig continuous_config(Fidelity fidelity, std::uint64_t seed) {
  StudyConfig c;  // every scheme, both systems, Table 3.1 bounds, uniform draws
  c.fidelity = fidelity;
  c.with_grid = false;  // 42/63/84 min
  c.samples = kSamples;
  c.seed = seed;
  c.threads = 2;
  c.test.dv_pulse_mps = 0;
  c.test.position_resolution_m = 0;
  c.test.torquer_pulse_rad = 0;
  c.test.sway.velocity_rms_mps = 0;
  return c;
}

StudyConfig measured_config(Fidelity fidelity, std::uint64_t seed, std::uint64_t samples) {
  StudyConfig c = continuous_config(fidelity, seed);
  c.test = TestRunOptions{};  // 0.1 ft/s pulses, 3 ft resolution, 1 arcsec torquer pulses, sway off
  c.samples = samples;
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

void expect_rms2_agrees(const Study& st) {
  ASSERT_EQ(st.layout.outputs.size(), static_cast<std::size_t>(kOutputsPerStudy));
  const StudyAccumulator acc = run(st);
  double largest = 0;
  for (std::size_t o = 0; o < st.layout.outputs.size(); ++o) {
    ASSERT_GT(st.map.predicted_var_r2()[o], 0.0) << describe(st.layout, o);
    ASSERT_EQ(acc.outputs()[o].count(), kSamples);
    const R2Check c = r2_check(acc.outputs()[o], st.map, o);
    largest = std::max(largest, std::fabs(c.deviation / c.bound * kZ));
    EXPECT_TRUE(c.pass()) << describe(st.layout, o) << ": mean r² − E r² = " << c.deviation << " m², bound ±" << c.bound
                          << " (z = " << c.deviation / c.bound * kZ << ")";
  }
  std::cout << fmt::format("{}: largest |z| {:.2f} of {} outputs (accept <= {:.2f})\n", to_string(st.c.fidelity),
                           largest, kOutputsPerStudy, kZ);
}

TEST(CompensationCovariance, ContinuousOutputsPaperFidelity) {
  std::cout << fmt::format("z = {:.3f} per check (alpha {:.2e})\n", kZ, kAlphaPerCheck);
  expect_rms2_agrees(Study(continuous_config(Fidelity::kPaper, 2101)));
}

TEST(CompensationCovariance, ContinuousOutputsLinearFidelity) {
  expect_rms2_agrees(Study(continuous_config(Fidelity::kLinear, 2102)));
}

TEST(CompensationCovariancePower, TenPercentWiderGyroDriftBoundFailsForEveryScheme) {
  const Study null_study(continuous_config(Fidelity::kLinear, 2103));
  StudyConfig wider = continuous_config(Fidelity::kLinear, 2103);
  for (const int j : select_uncertainties("gyro_drift")) wider.uncertainties.at(j).bound_si *= kBoundFactor;
  const Study mc(wider);  // the Monte Carlo side, and the alternative's exact moments
  const double n = static_cast<double>(kSamples);
  std::vector<std::size_t> relied;
  std::vector<int> per_scheme(kSchemes, 0);
  double total_miss = 0;
  for (std::size_t o = 0; o < null_study.layout.outputs.size(); ++o) {
    const double e0 = std::pow(null_study.map.predicted_rms()[o], 2), e1 = std::pow(mc.map.predicted_rms()[o], 2);
    const double power = two_sided_power(e1 - e0, std::sqrt(null_study.map.predicted_var_r2()[o] / n),
                                         std::sqrt(mc.map.predicted_var_r2()[o] / n));
    if (power < kPowerRequired) continue;
    relied.push_back(o);
    total_miss += 1 - power;
    ++per_scheme[static_cast<std::size_t>(
        std::find(null_study.c.schemes.begin(), null_study.c.schemes.end(), null_study.layout.outputs[o].scheme) -
        null_study.c.schemes.begin())];
  }
  for (int i = 0; i < kSchemes; ++i) {
    std::cout << fmt::format("scheme {}: {} outputs with power >= {}\n", to_string(null_study.c.schemes[i]),
                             per_scheme[i], kPowerRequired);
    ASSERT_GE(per_scheme[i], 1) << "no output of scheme " << to_string(null_study.c.schemes[i])
                                << " can see a 10% wider gyro-drift bound";
  }
  ASSERT_LE(total_miss, 1 - kPowerRequired);
  const StudyAccumulator acc = run(mc);
  for (const std::size_t o : relied) {
    const R2Check c = r2_check(acc.outputs()[o], null_study.map, o);
    EXPECT_FALSE(c.pass()) << describe(null_study.layout, o)
                           << ": the check cannot see gyro-drift bounds 10% too wide (deviation " << c.deviation
                           << ", bound " << c.bound << ")";
  }
}

// Part 2: measured, printed; sanity only.
//  (a) the engine's run against the covariance, as `insmc run` and
//      `insmc covariance` report them: (RMS_MC − RMS_cov)/RMS_cov with the
//      ± z half-width of the Monte Carlo RMS;
//  (b) paired: the same samples (same seed and index, so the same x, fresh
//      draws and counter phases) evaluated with the measurement model on and
//      off, so the uncertainties' own sampling noise cancels: the increase of
//      E[r²] that the pulses and the resolution cause, Δ_MC (± its standard
//      error), against the covariance model's Δ_cov (the noise inputs' share);
//      their difference relative to E_cov[r²] is the model's error.
// Measured, not tested: sized for Debug + ASan (the paired differences are
// far less noisy than the RMS itself).
constexpr std::uint64_t kMeasuredSamples = 10000;
constexpr std::uint64_t kPairedSamples = 2000;

void measure_pulse_effect(Fidelity fidelity, std::uint64_t seed) {
  const Study st(measured_config(fidelity, seed, kMeasuredSamples));
  // The same fits as the measured study (with continuous data every term is
  // resolvable and U4 would be fitted too; with 0.1 ft/s pulses at T = 15 min
  // it is not, Table 4.3), so that only the measurement noise differs.
  StudyConfig off_config = continuous_config(fidelity, seed);
  off_config.test.fit_u4 = FitU4::kNo;
  const Study off(off_config);
  for (int j = 0; j < kSystems; ++j) ASSERT_EQ(st.map.fitted_terms(j), off.map.fitted_terms(j));
  const StudyAccumulator acc = run(st);
  const double n = static_cast<double>(kMeasuredSamples);
  // (b): paired sums of d = r_on² − r_off² per output.
  const std::size_t n_out = st.layout.outputs.size();
  std::vector<double> sum_d(n_out, 0.0), sum_d2(n_out, 0.0);
  const Sampler sampler(st.c.uncertainties);
  for (std::uint64_t i = 0; i < kPairedSamples; ++i) {
    const UncertaintyVector x = sampler.draw(seed, i);
    const std::vector<double> on = evaluate_sample(st.c, st.map, st.layout, i, x);
    const std::vector<double> no = evaluate_sample(off.c, off.map, off.layout, i, x);
    for (std::size_t o = 0; o < n_out; ++o) {
      const double d = on[o] * on[o] - no[o] * no[o];
      sum_d[o] += d, sum_d2[o] += d * d;
    }
  }
  const double np = static_cast<double>(kPairedSamples);
  std::cout << fmt::format(
      "{} level, ΔV 0.1 ft/s, resolution 3 ft, torquer 1 arcsec; horizontal:\n"
      "  (a) RMS: covariance, MC (n = {}), (MC − cov)/cov ± {:.1f}σ;\n"
      "  (b) paired (n = {}): the measurement noise's added E[r²] as an RMS, covariance model vs MC, and "
      "(Δ_MC − Δ_cov)/E_cov[r²] ± 2 s.e.\n",
      to_string(fidelity), kMeasuredSamples, kZ, kPairedSamples);
  double worst_a = 0, worst_b = 0;
  for (std::size_t o = 0; o < n_out; ++o) {
    const OutputSpec& s = st.layout.outputs[o];
    const double cov = st.map.predicted_rms()[o], cov_off = off.map.predicted_rms()[o];
    const double mc = std::sqrt(acc.outputs()[o].sum_squares() / n);
    const double rel = mc / cov - 1;
    // δ(RMS)/RMS ≈ δ(m̂2)/(2 E r²) with sd(m̂2) from the exact Var(r²).
    const double half = kZ * std::sqrt(st.map.predicted_var_r2()[o] / n) / (2 * cov * cov);
    const double delta_cov = cov * cov - cov_off * cov_off, delta_mc = sum_d[o] / np;
    const double se = std::sqrt(std::max(0.0, sum_d2[o] / np - delta_mc * delta_mc) / np);
    const double model_error = (delta_mc - delta_cov) / (cov * cov);
    worst_a = std::max(worst_a, std::fabs(rel));
    worst_b = std::max(worst_b, std::fabs(model_error));
    EXPECT_LT(std::fabs(rel), kSanityFraction) << describe(st.layout, o);
    EXPECT_LT(std::fabs(model_error), kSanityFraction) << describe(st.layout, o);
    if (s.axis != Axis::kHorizontal) continue;
    auto as_rms_ft = [](double d) { return std::copysign(std::sqrt(std::fabs(d)), d) / kFtToM; };
    std::cout << fmt::format(
        "  {:<8} sys {} {:2} min: (a) {:6.0f} {:6.0f} ft {:+5.2f}% ± {:.2f}%  (b) noise {:5.0f} ft (cov) "
        "{:5.0f} ft (MC), {:+.3f}% ± {:.3f}%\n",
        to_string(s.scheme), system_number(s.system),
        std::lround(st.layout.times_s[static_cast<std::size_t>(s.time_index)] / 60), cov / kFtToM, mc / kFtToM,
        100 * rel, 100 * half, as_rms_ft(delta_cov), as_rms_ft(delta_mc), 100 * model_error, 200 * se / (cov * cov));
  }
  std::cout << fmt::format("  largest over all {} outputs: |(a)| {:.2f}%, |(b)| {:.3f}%\n", kOutputsPerStudy,
                           100 * worst_a, 100 * worst_b);
}

TEST(CompensationCovarianceMeasured, PulsesAndResolutionPaperFidelity) { measure_pulse_effect(Fidelity::kPaper, 2104); }

TEST(CompensationCovarianceMeasured, PulsesAndResolutionLinearFidelity) {
  measure_pulse_effect(Fidelity::kLinear, 2105);
}

}  // namespace
}  // namespace insmc::mc
