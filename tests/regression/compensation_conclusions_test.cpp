// Regression: the report's conclusions about the compensation schemes
// (§5.1.2, §5.2, §5.3, §6), reproduced or the difference recorded, with the
// exact linear covariance of the whole pipeline (StudyMap: the test-run fits
// with the pulses and the resolution as additive noise, the realignment, the
// alignment-phase measurements) at the paper and linear levels, Table 3.1
// defaults, T = 15 min, realignment 10 min; and the Monte Carlo of the
// study behind the text figures of §5.2.
//
// The report's conclusion (§6): "A combination of the methods used in
// paragraphs 5.1.1 and 5.1.2 seems to give the best results provided that
// the change in the uncertainties from alignment to alignment is small";
// of 5.2 and 5.3 "the last method seems to be the most accurate"; 5.4
// "fails ... to detect changes in the I.N.S. uncertainties when the system is
// switched from the alignment phase to the navigation phase".
// What the model gives (horizontal RMS, printed below): at 84 min 5.4 is the
// smallest for both systems at both levels. Physics: 5.4 is the only scheme
// that estimates ω_doz (from the z torquer command, (5.14)), which no test
// run sees (§5.1.2: Û2, Û3 "do not give any information about ω_doz") and
// which dominates the residual U4 (2ω_doz cos L0/ω_ie, (3.29d)) of every
// other scheme at 84 min; 5.4's blind spot, the switch-over changes ζ_r,
// ∂f_r, enters only U'2 (5.20), whose time function 1 − cos ω_s t vanishes
// at one Schuler period (84.4 min) and peaks at 42 min, where 5.4 is far
// behind 5.2/5.3. The combination is the best of the realignment schemes (to
// within 1%), and with no alignment-to-alignment change (ζ_r = ∂f_r = 0, the
// report's proviso) the 5.1 family is the best of all at 42 and 63 min. 5.2
// and 5.3 agree to within 2% at every report time: 5.3's better (1 − cos)
// coefficient is worth little against the common U4 terms, and its Δf̂(T)
// from 0.1 ft/s pulses is no more accurate than the position fit.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

#include "lib/uncertainty/catalogue.h"
#include "montecarlo/study/engine/engine.h"

namespace insmc::mc {
namespace {

struct Study {
  explicit Study(const StudyConfig& config) : c(config), layout(make_layout(c)), map(c, layout) {}
  StudyConfig c;
  StudyLayout layout;
  StudyMap map;
  int scheme_index(Scheme s) const {
    return static_cast<int>(std::find(c.schemes.begin(), c.schemes.end(), s) - c.schemes.begin());
  }
  double rms_ft(Scheme s, int system_j, int time_k) const {
    return map.predicted_rms()[static_cast<std::size_t>(
               layout.index(scheme_index(s), system_j, time_k, Axis::kHorizontal))] /
           kFtToM;
  }
  double share(Scheme s, int system_j, int time_k, const std::vector<int>& slots) const {
    const auto& sh =
        shares[static_cast<std::size_t>(layout.index(scheme_index(s), system_j, time_k, Axis::kHorizontal))];
    double sum = 0;
    for (int q : slots) sum += sh[static_cast<std::size_t>(q)];
    return sum;
  }
  std::vector<std::vector<double>> shares = map.budget_shares();
};

StudyConfig defaults(Fidelity f) {
  StudyConfig c;
  c.fidelity = f;
  c.with_grid = false;  // 42/63/84 min
  return c;
}

constexpr int k42 = 0, k63 = 1, k84 = 2;
const Scheme kRealigning[] = {Scheme::k5_1_1, Scheme::k5_1_2, Scheme::kCombined};
// Equal within the covariance's own modelling (the ranking is not asserted
// below this).
constexpr double kTieFraction = 0.01;
// 5.2 against 5.3: their residuals differ only in the (1 − cos ω_s t')
// coefficient and its estimation noise.
constexpr double kSameFraction = 0.02;

void print_ranking(const Study& st, const char* label) {
  for (int j = 0; j < 2; ++j) {
    for (int k = 0; k < 3; ++k) {
      std::vector<std::pair<double, Scheme>> v;
      for (Scheme s : st.c.schemes) v.emplace_back(st.rms_ft(s, j, k), s);
      std::sort(v.begin(), v.end());
      std::string line = fmt::format("{} {:<6} system {} t = {:2.0f} min:", label, to_string(st.c.fidelity), j + 1,
                                     st.layout.times_s[static_cast<std::size_t>(k)] / 60);
      for (const auto& [rms, s] : v) line += fmt::format(" {} {:.0f},", to_string(s), rms);
      std::cout << line << " ft\n";
    }
  }
}

TEST(SchemeConclusions, SchemeRankingAt84Min) {
  for (Fidelity f : {Fidelity::kPaper, Fidelity::kLinear}) {
    const Study st(defaults(f));
    print_ranking(st, "Table 3.1");
    const std::vector<int> drift_z = {uncertainty_slot::kGyroDrift + 2};
    const std::vector<int> switch_over = {uncertainty_slot::kMisalignAlign, uncertainty_slot::kMisalignAlign + 1, uncertainty_slot::kMisalignAlign + 2,
                                          uncertainty_slot::kBiasChangeAlign, uncertainty_slot::kBiasChangeAlign + 1};
    for (int j = 0; j < 2; ++j) {
      const std::string where = fmt::format("{}, system {}", to_string(f), j + 1);
      for (int k = 0; k < 3; ++k) {
        for (Scheme s : st.c.schemes) {
          if (s != Scheme::kNone) {
            EXPECT_LT(st.rms_ft(s, j, k), st.rms_ft(Scheme::kNone, j, k)) << where;
          }
        }
      }
      // 5.4 smallest at 84 min, and why.
      for (Scheme s : st.c.schemes) {
        if (s != Scheme::k5_4) {
          EXPECT_LT(st.rms_ft(Scheme::k5_4, j, k84), st.rms_ft(s, j, k84)) << where << " " << to_string(s);
        }
      }
      EXPECT_LT(st.share(Scheme::k5_4, j, k84, drift_z), 0.01) << where;
      for (Scheme s : {Scheme::k5_1_1, Scheme::k5_1_2, Scheme::kCombined, Scheme::k5_2, Scheme::k5_3})
        EXPECT_GT(st.share(s, j, k84, drift_z), 0.3) << where << " " << to_string(s);
      EXPECT_LT(st.share(Scheme::k5_4, j, k84, switch_over), 0.05) << where;
      EXPECT_GT(st.share(Scheme::k5_4, j, k42, switch_over), 0.5) << where;
      // §5.2: realigning beats resetting at 84 min (U4 ω_ie T in U'3, (5.9b)).
      for (Scheme r : kRealigning)
        for (Scheme s : {Scheme::k5_2, Scheme::k5_3}) EXPECT_LT(st.rms_ft(r, j, k84), st.rms_ft(s, j, k84)) << where;
      // The combination: the best realignment scheme to within a tie.
      EXPECT_LE(st.rms_ft(Scheme::kCombined, j, k84),
                (1 + kTieFraction) * std::min(st.rms_ft(Scheme::k5_1_1, j, k84), st.rms_ft(Scheme::k5_1_2, j, k84)))
          << where;
      for (int k = 0; k < 3; ++k)
        EXPECT_NEAR(st.rms_ft(Scheme::k5_3, j, k), st.rms_ft(Scheme::k5_2, j, k),
                    kSameFraction * st.rms_ft(Scheme::k5_2, j, k))
            << where << " t index " << k;
    }
  }
}

// The report's proviso: "provided that the change in the uncertainties from
// alignment to alignment is small" — ζ_r and ∂f_r set to zero. The 5.1
// family is then the best at 42 and 63 min, and the combination the best of
// it at 63 min. At 42 min, where 1 − cos ω_s t peaks, system 1's 5.1.1 beats
// the combination: the torquer compensation leaves (ω_dox,y/F(0))_p in U'2
// ((5.7a); the report: "U'2x(1), U'2y(1)" increased), which 5.1.1 removes.
TEST(SchemeConclusions, WithoutAlignmentToAlignmentChangeThe51FamilyLeadsAt42And63Min) {
  for (Fidelity f : {Fidelity::kPaper, Fidelity::kLinear}) {
    StudyConfig c = defaults(f);
    c.uncertainties.apply_dist("misalign_align=zero");
    c.uncertainties.apply_dist("bias_change_align=zero");
    const Study st(c);
    print_ranking(st, "no ζ_r, ∂f_r");
    for (int j = 0; j < 2; ++j) {
      for (int k : {k42, k63}) {
        const std::string where = fmt::format("{}, system {}, time index {}", to_string(f), j + 1, k);
        double best_51 = 1e300, best_other = 1e300;
        for (Scheme s : st.c.schemes) {
          const bool is_51 = std::find(std::begin(kRealigning), std::end(kRealigning), s) != std::end(kRealigning);
          double& best = is_51 ? best_51 : best_other;
          best = std::min(best, st.rms_ft(s, j, k));
        }
        EXPECT_LT(best_51, best_other) << where;
        if (k == k63) {
          EXPECT_LE(st.rms_ft(Scheme::kCombined, j, k), (1 + kTieFraction) * best_51) << where;
        }
      }
      if (j == 0) {
        EXPECT_LT(st.rms_ft(Scheme::k5_1_1, j, k42), st.rms_ft(Scheme::kCombined, j, k42)) << to_string(f);
      }
    }
  }
}

// The study of §5.2's text figures, `--dist all=zero --dist
// gyro_drift_z=fixed:10meru --scheme 5.2 --test-duration 20min`, as the
// Monte Carlo runs it (0.1 ft/s pulses, 3 ft resolution). Measured and
// printed: the report quotes the U4 ½ω_ie²T² term (2,300 ft at t' = 42 min)
// and the U4 ω_ie T term (1.56 n.m. at t' = 84 min) alone (checked from the
// maps in tests/unit/lib/compensation/conclusions_test.cpp); the whole
// residual adds the U4 t'² term and the fit's aliasing. With this prior U3
// has zero prior RMS, so the pipeline fits U1, U2 only (resolvable_terms),
// and the U4 signal aliases into Û2 alone.
constexpr std::uint64_t kFigureSamples = 2048;  // the result varies only with the counter phases

TEST(SchemeConclusions, MonteCarloOfTheTextFigureStudy) {
  for (Fidelity f : {Fidelity::kPaper, Fidelity::kLinear}) {
    StudyConfig c = defaults(f);
    c.schemes = {Scheme::k5_2};
    c.test.duration_s = 20 * 60.0;
    c.samples = kFigureSamples;
    c.threads = 2;
    c.uncertainties.apply_dist("all=zero");
    c.uncertainties.apply_dist("gyro_drift_z=fixed:10meru");
    const Study st(c);
    const StudyAccumulator acc = run_blocks(st.c, st.map, 0, block_count(st.c.samples));
    for (int j = 0; j < 2; ++j) {
      EXPECT_EQ(st.map.fitted_terms(j), "U1,U2") << "U3 has zero prior RMS in this study";
      for (int k : {k42, k84}) {
        const std::size_t ox = static_cast<std::size_t>(st.layout.index(0, j, k, Axis::kX));
        const std::size_t oh = static_cast<std::size_t>(st.layout.index(0, j, k, Axis::kHorizontal));
        const OutputSummary x = acc.outputs()[ox].summarize(c.confidence);
        const OutputSummary h = acc.outputs()[oh].summarize(c.confidence);
        std::cout << fmt::format(
            "{} system {} t' = {:.0f} min (fitted {}): x mean {:.0f} ft (sd {:.1f} ft; covariance mean {:.0f} ft), "
            "horizontal RMS {:.0f} ft = {:.2f} n.m.\n",
            to_string(f), j + 1, st.layout.times_s[static_cast<std::size_t>(k)] / 60, st.map.fitted_terms(j),
            x.mean / kFtToM, x.std / kFtToM, st.map.predicted_mean()[ox] / kFtToM, h.rms / kFtToM, h.rms / kNmiToM);
        // Sanity: the pulses move the result by far less than the quoted terms.
        EXPECT_NEAR(x.mean, st.map.predicted_mean()[ox], 0.01 * std::fabs(st.map.predicted_mean()[ox]));
      }
    }
  }
}

}  // namespace
}  // namespace insmc::mc
