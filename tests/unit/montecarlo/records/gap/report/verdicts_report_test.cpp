// Tests for montecarlo/records/gap/report/verdicts_report.h: section 1 states one
// verdict per null, in one order (the model, then the unit's own noise),
// each named for what it compares and worded as its p says.
#include "montecarlo/records/gap/report/verdicts_report.h"

#include <gtest/gtest.h>

#include <string>

namespace insmc::gap {
namespace {

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

Diagnosis through_the_import() {
  Diagnosis d;
  d.runs = 6;
  d.against_model = {true, 20.6, 0.9, 0.0005, true, 20.6, 0.91, 0.38};
  d.gap = d.unmodelled_gap = 0.445;
  d.null_gap_median = 0.267;
  d.null_gap_critical = d.unmodelled_critical = 0.656;
  d.p_value = 0.131;
  d.own_noise_less = {0.0, 0.0, 1.0, false};
  return d;
}

TEST(Verdicts, TheModelsComesFirstThenTheUnitsOwnNoiseEachWordedAsItsP) {
  const std::string md = verdicts_markdown(through_the_import());
  const auto model = md.find("1. **Against the model**");
  const auto own = md.find("2. **Against the unit's own noise**");
  ASSERT_NE(model, std::string::npos) << md;
  ASSERT_NE(own, std::string::npos) << md;
  EXPECT_LT(model, own);
  const std::string first = md.substr(model, own - model), second = md.substr(own);
  EXPECT_TRUE(has(first, "G+ = 20.6, p = 0.0005, alpha = 0.01: **significant gap**")) << first;
  EXPECT_TRUE(has(first, "a perfect sensor")) << first;
  EXPECT_TRUE(has(second, "G+ = 0.445, p = 0.131, alpha = 0.01: **no significant gap**")) << second;
  EXPECT_TRUE(has(second, "the raw stage's fitted noise")) << second;
  EXPECT_TRUE(has(md, "The gap against the model is what the sensor's own noise makes")) << md;
}

TEST(Verdicts, RecordsOfTheModelItselfHaveOneVerdictAgainstTheModel) {
  Diagnosis d;
  d.runs = 20;
  d.gap = d.unmodelled_gap = 2.1;
  d.p_value = 0.0005;
  d.significant = true;
  const std::string md = verdicts_markdown(d);
  EXPECT_TRUE(has(md, "**Against the model**, judged on null files of truth-level runs of the model itself")) << md;
  EXPECT_FALSE(has(md, "own noise")) << md;
  EXPECT_TRUE(has(md, "**significant gap**")) << md;
  const std::string j = verdicts_json(d).dump(-1);
  EXPECT_TRUE(has(j, "\"against\":\"the model\"")) << j;
  EXPECT_FALSE(has(j, "own noise")) << j;
}

TEST(Verdicts, GPlusIsWordedAsItsOwnPAndTheJointTestBesideIt) {
  // Significant through the estimates against the prior, not through G+:
  // "G+ ... p = 0.794: significant gap" said the joint decision of G+'s p.
  Diagnosis d;
  d.runs = 5;
  d.gap = 0.568;
  d.unmodelled_gap = 0.0854;
  d.p_value = 0.794;
  d.estimate_test.measured = true;
  d.estimate_test.combined_p = 0.0005;
  d.significant = true;
  const std::string md = verdicts_markdown(d);
  EXPECT_TRUE(has(md, "G+ = 0.0854, p = 0.794, alpha = 0.01: **no significant gap**; jointly with the test run's "
                      "estimates against the prior (below), p = 0.0005: **significant gap**"))
      << md;
  const std::string j = verdicts_json(d).dump(-1);
  EXPECT_TRUE(has(j, "\"p_value\":0.794,\"significant\":false")) << j;
}

TEST(Verdicts, TheJsonListsBothInTheReportsOrder) {
  const std::string j = verdicts_json(through_the_import()).dump(-1);
  const auto model = j.find("\"against\":\"the model\"");
  const auto own = j.find("\"against\":\"the unit's own noise\"");
  ASSERT_NE(model, std::string::npos) << j;
  ASSERT_NE(own, std::string::npos) << j;
  EXPECT_LT(model, own);
  EXPECT_TRUE(has(j.substr(model, own - model), "\"p_value\":0.0005,\"significant\":true")) << j;
  EXPECT_TRUE(has(j.substr(own), "\"p_value\":0.131,\"significant\":false")) << j;
}

}  // namespace
}  // namespace insmc::gap
