// Tests for montecarlo/records/gap/report/leading_finding.h: the report's first
// sentence follows the order the decision needs (outside the priors or the
// model's counts, an unmodelled effect, pessimistic, agreement).
#include "montecarlo/records/gap/report/leading_finding.h"

#include <gtest/gtest.h>

#include "lib/units/units.h"

namespace insmc::gap {
namespace {

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

Diagnosis agreeing() {
  Diagnosis d;
  d.site = {{"dv_pulse_mps", 0.1 * kFtpsToMps, "header", "stated"}, {"position_resolution_m", 3 * kFtToM, "header", "stated"}};
  return d;
}

TEST(LeadingFinding, AgreementIsSaidWhenNothingElseIs) {
  EXPECT_TRUE(has(leading_finding(agreeing()), "agree with the model")) << leading_finding(agreeing());
}

TEST(LeadingFinding, AnUnmodelledEffectIsNamedWithItsEffectArgumentAndShrink) {
  Diagnosis d = agreeing();
  d.significant = true;
  d.first.top = "thermal_transient";
  CandidateResult c;
  c.effect = "thermal_transient";
  c.shrink = 0.88;
  c.null_shrink = -0.07;
  c.as_effect = "thermal_transient:bias=0.2mg";
  d.first.ranking.push_back(c);
  const std::string f = leading_finding(d);
  EXPECT_TRUE(has(f, "An unmodelled effect: thermal_transient")) << f;
  EXPECT_TRUE(has(f, "thermal_transient:bias=0.2mg")) << f;
  EXPECT_TRUE(has(f, "88 %")) << f;
}

TEST(LeadingFinding, AnEffectNamedByTheEstimatesKeepsItsOwnEvidenceApartFromTheRankings) {
  // The estimates against the prior named a class; the residuals' ranking
  // put another effect first. The sentence gave the class the ranking's
  // effect argument and shrink.
  Diagnosis d = agreeing();
  d.significant = true;
  d.first.top = "anisoelastic_drift|deflection_of_vertical";
  d.estimate_test.measured = true;
  d.estimate_test.replaced_top = "thermal_transient";
  d.estimate_test.scores = {{"anisoelastic_drift", 1.41}, {"deflection_of_vertical", 0.63}};
  CandidateResult c;
  c.effect = "thermal_transient";
  c.shrink = 0.26;
  c.null_shrink = 0.10;
  c.as_effect = "thermal_transient:bias=-0.03mg";
  d.first.ranking.push_back(c);
  const std::string f = leading_finding(d);
  EXPECT_TRUE(has(f, "An effect inside the priors: anisoelastic_drift|deflection_of_vertical (named by the test "
                     "run's estimates against the prior, anisoelastic_drift first at a held-out gain of 1.41 nats"))
      << f;
  EXPECT_TRUE(has(f, "the first-ranked candidate, thermal_transient, closes 26 %")) << f;
  EXPECT_FALSE(has(f, "bias=-0.03mg")) << "the ranking's effect argument is not the class's: " << f;
}

TEST(LeadingFinding, PulsesFarFromTheModelsComeBeforeAnyEffect) {
  Diagnosis d = agreeing();
  d.site[0] = {"dv_pulse_mps", 1.0 * kFtpsToMps, "inferred", "a lattice"};
  d.significant = true;
  d.first.top = "quantization";
  d.first.ranking.push_back(CandidateResult{});
  const std::string f = leading_finding(d);
  EXPECT_TRUE(has(f, "counts lie outside the model's assumptions")) << f;
  EXPECT_TRUE(has(f, "1 ft/s (inferred from the rows, 10 times the model's 0.1 ft/s)")) << f;
  // Within a factor 2 of the model's, and continuous outputs, are not "far".
  d.site[0].value = 0.15 * kFtpsToMps;
  EXPECT_FALSE(has(leading_finding(d), "outside")) << leading_finding(d);
  d.site[0].value = 0.0;
  EXPECT_FALSE(has(leading_finding(d), "outside")) << leading_finding(d);
}

TEST(LeadingFinding, ARawStageFarOutsideThePriorsLeadsPerSensor) {
  Diagnosis d = agreeing();
  d.raw_gyro_ratio = 253;
  d.raw_accel_ratio = 29.4;
  d.significant = true;
  const std::string f = leading_finding(d);
  EXPECT_TRUE(has(f, "outside the model's priors")) << f;
  EXPECT_TRUE(has(f, "gyros' noise is 253 times and its accelerometers' 29.4 times")) << f;
}

TEST(LeadingFinding, APessimisticModelIsSaidWhenNoGapIsAbove) {
  Diagnosis d = agreeing();
  d.pessimistic.significant = true;
  EXPECT_TRUE(has(leading_finding(d), "pessimistic")) << leading_finding(d);
}

/// Records through the import: significant against the model alone (G+
/// 20.6), not beyond the unit's own noise (G+ 0.445, p 0.131).
Diagnosis imported(double gyro_ratio, double accel_ratio) {
  Diagnosis d = agreeing();
  d.raw_gyro_ratio = gyro_ratio;
  d.raw_accel_ratio = accel_ratio;
  d.against_model = {true, 20.6, 0.9, 0.0005, true, 20.6, 0.9, 0.4};
  d.unmodelled_gap = 0.445;
  d.p_value = 0.131;
  d.significant = false;
  return d;
}

TEST(LeadingFinding, AUnitWithinThePriorsWhoseGapIsItsOwnNoiseIsSaidToBe) {
  const std::string f = leading_finding(imported(0.04, 0.02));
  EXPECT_TRUE(has(f, "The gap against the model is the unit's own sensor noise")) << f;
  EXPECT_TRUE(has(f, "(raw-sensor stage: within them)")) << f;
  EXPECT_FALSE(has(f, "An unmodelled effect")) << f;
  // Both verdicts, the model's first.
  const auto model = f.find("Against the model: a significant gap (G+ = 20.6, p = 0.0005)");
  const auto own = f.find("against the unit's own noise through the import: no significant gap (G+ = 0.445, p = 0.131)");
  ASSERT_NE(model, std::string::npos) << f;
  ASSERT_NE(own, std::string::npos) << f;
  EXPECT_LT(model, own);
  // Between 1 and the "far" factor: the ratio, not "within".
  EXPECT_FALSE(has(leading_finding(imported(1.5, 0.5)), "within them")) << leading_finding(imported(1.5, 0.5));
}

TEST(LeadingFinding, AnImportedUnitThatAgreesWithBothNullsIsSaidToAgreeWithBoth) {
  Diagnosis d = imported(0.04, 0.02);
  d.against_model.significant = false;
  d.against_model.p_value = 0.3;
  const std::string f = leading_finding(d);
  EXPECT_TRUE(has(f, "agree with the model and with the unit's own noise")) << f;
  EXPECT_TRUE(has(f, "Against the model: no significant gap")) << f;
}

TEST(LeadingFinding, AnEffectBeyondTheUnitsOwnNoiseIsNamedWithBothVerdicts) {
  Diagnosis d = imported(0.04, 0.02);
  d.p_value = 0.002;
  d.significant = true;
  d.first.top = "thermal_transient";
  CandidateResult c;
  c.effect = "thermal_transient";
  c.shrink = 0.7;
  d.first.ranking.push_back(c);
  const std::string f = leading_finding(d);
  EXPECT_TRUE(has(f, "An unmodelled effect: thermal_transient")) << f;
  EXPECT_TRUE(has(f, "against the unit's own noise through the import: a significant gap (G+ = 0.445, p = 0.002)")) << f;
}

TEST(LeadingFinding, AUnitOutsideThePriorsGivesBothVerdictsAfterItsRatios) {
  const std::string f = leading_finding(imported(618, 3.8));
  const auto ratios = f.find("gyros' noise is 618 times");
  const auto model = f.find("Against the model:");
  ASSERT_NE(ratios, std::string::npos) << f;
  ASSERT_NE(model, std::string::npos) << f;
  EXPECT_LT(ratios, model);
}

}  // namespace
}  // namespace insmc::gap
