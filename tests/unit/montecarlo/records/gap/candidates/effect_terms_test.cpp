// A finding in the effect's own terms (montecarlo/records/gap/ranking/effect_terms.h
// and the candidates' to_effect_terms): the thermal transient the diagnosis
// fits at switch-over is reported at switch-on, the inverse of what the
// truth simulator's effect does to its switch-on value (lib/truth/effects).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "lib/truth/effect.h"
#include "lib/truth/perturbations.h"
#include "lib/units/units.h"
#include "montecarlo/records/gap/candidates/candidates.h"
#include "montecarlo/records/gap/ranking/effect_terms.h"

namespace insmc::gap {
namespace {

const gap::Candidate& candidate(const std::string& name) {
  for (const gap::Candidate& c : gap::candidate_registry())
    if (c.name == name) return c;
  throw std::runtime_error("no candidate " + name);
}

TEST(EffectTerms, ATransientAtSwitchOverIsReportedAtSwitchOnAsTheTruthDefinesIt) {
  // The truth effect of switch-on bias B, drift D, tau, warm-up w leaves
  // B e^{-w/tau} at switch-over (what the records see); the candidate's
  // conversion must give B back, for the warm-up the site says.
  EffectSpec spec = parse_effect("thermal_transient:bias=0.2mg,drift=3meru,tau=1200s,warmup=600s");
  const Perturbations p = realize_effects(std::span<const EffectSpec>(&spec, 1), EffectContext{});
  runs::RecordSite site;
  site.warmup_s = 600.0;
  std::vector<double> fitted = {p.alignment_bias_mps2[0], p.alignment_drift_radps[0], 1200.0};
  ASSERT_LT(fitted[0], 0.2 * kMgToMps2);  // the records see less than the switch-on value
  candidate("thermal_transient").to_effect_terms(fitted, site);
  EXPECT_NEAR(fitted[0], 0.2 * kMgToMps2, 1e-12 * kMgToMps2);
  EXPECT_NEAR(fitted[1], 3.0 * kMeruToRadps, 1e-12 * kMeruToRadps);
  EXPECT_EQ(fitted[2], 1200.0);
}

TEST(EffectTerms, TheFindingIsAnEffectArgumentSimulateAccepts) {
  CandidateResult c;
  c.effect = "thermal_transient";
  c.parameters = {{"bias", Dimension::kAcceleration, 0.2 * kMgToMps2, 0, 0, false, {}},
                  {"drift", Dimension::kAngularRate, 3 * kMeruToRadps, 0, 0, false, {}},
                  {"tau", Dimension::kTime, 1200.0, 0, 0, false, {}}};
  runs::RecordSite site;
  EffectArgument a = effect_argument(c, site);
  EXPECT_EQ(a.text, "thermal_transient:bias=0.2mg,drift=3meru,tau=1.2e+03s,warmup=900s");
  ASSERT_EQ(a.kept.size(), 1U);
  EXPECT_NE(a.kept[0].find("no warmup_s in the header"), std::string::npos) << a.kept[0];
  const EffectSpec back = parse_effect(a.text);
  EXPECT_NEAR(back.value("bias"), 0.2 * kMgToMps2, 1e-9);
  site.warmup_s = 300.0;
  site.warmup_from_header = true;
  a = effect_argument(c, site);
  EXPECT_NE(a.text.find("warmup=300s"), std::string::npos) << a.text;
  EXPECT_NE(a.kept[0].find("the records' warmup_s"), std::string::npos) << a.kept[0];
  // A candidate whose parameters are not the effect's has no such form.
  CandidateResult gravity;
  gravity.effect = "gravity_model";
  gravity.parameters = {{"north_offset", Dimension::kAcceleration, 1e-5, 0, 0, false, {}}};
  EXPECT_TRUE(effect_argument(gravity, site).text.empty());
}

}  // namespace
}  // namespace insmc::gap
