// A class of candidates the ranking cannot tell apart is reported with the
// test that would (montecarlo/records/gap/ranking/statements.h).
#include <gtest/gtest.h>

#include "montecarlo/records/gap/candidates/candidates.h"
#include "montecarlo/records/gap/ranking/statements.h"

namespace insmc::gap {
namespace {

TEST(Statements, EveryCandidateSaysWhatTestShowsItsOwnSignature) {
  for (const gap::Candidate& c : gap::candidate_registry()) EXPECT_FALSE(c.told_apart_by.empty()) << c.name;
}

TEST(Statements, AClassNamesTheTestOfEachMemberOrTheOneTheyShareOnce) {
  const std::string two = what_tells_apart("anisoelastic_drift", "deflection_of_vertical");
  EXPECT_NE(two.find("another orientation"), std::string::npos) << two;
  EXPECT_NE(two.find("a second site"), std::string::npos) << two;
  const std::string same = what_tells_apart("bounds", "bounds");
  EXPECT_EQ(same.find("for bounds"), std::string::npos) << "one test, said once: " << same;
  EXPECT_NE(what_tells_apart("not_a_candidate", "bounds").find("more runs"), std::string::npos);
}

}  // namespace
}  // namespace insmc::gap
