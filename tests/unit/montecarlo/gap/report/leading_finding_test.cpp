// Tests for montecarlo/gap/report/leading_finding.h: the report's first
// sentence follows the order the decision needs (outside the priors or the
// model's counts, an unmodelled effect, pessimistic, agreement).
#include "montecarlo/gap/report/leading_finding.h"

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
  d.ranked = true;
  d.top = "thermal_transient";
  CandidateResult c;
  c.effect = "thermal_transient";
  c.shrink = 0.88;
  c.null_shrink = -0.07;
  c.as_effect = "thermal_transient:bias=0.2mg";
  d.ranking.push_back(c);
  const std::string f = leading_finding(d);
  EXPECT_TRUE(has(f, "An unmodelled effect: thermal_transient")) << f;
  EXPECT_TRUE(has(f, "thermal_transient:bias=0.2mg")) << f;
  EXPECT_TRUE(has(f, "88 %")) << f;
}

TEST(LeadingFinding, PulsesFarFromTheModelsComeBeforeAnyEffect) {
  Diagnosis d = agreeing();
  d.site[0] = {"dv_pulse_mps", 1.0 * kFtpsToMps, "inferred", "a lattice"};
  d.significant = true;
  d.ranked = true;
  d.top = "quantization";
  d.ranking.push_back(CandidateResult{});
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

}  // namespace
}  // namespace insmc::gap
