// Every effect of the truth simulator (lib/truth/effects/, the names
// `insmc effects` prints) has its candidate of the same name in the
// diagnosis (montecarlo/records/gap/candidates/): an effect without one could be
// simulated and withheld by gap-validate but never named by the diagnosis.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "lib/truth/effect.h"
#include "montecarlo/records/gap/candidates/candidates.h"

namespace insmc::gap {
namespace {

/// Candidates of the model itself, with no truth effect behind them
/// (candidates.h): priors wider than Table 3.1, terms the linear level drops.
const std::set<std::string> kModelLevel = {"bounds", "nonlinearity"};

std::set<std::string> effect_names() {
  std::set<std::string> names;
  for (const EffectInfo& e : effect_registry()) names.insert(std::string(e.name));
  return names;
}

std::set<std::string> candidate_names() {
  std::set<std::string> names;
  for (const Candidate& c : candidate_registry()) names.insert(c.name);
  return names;
}

TEST(CandidateRegistry, EveryTruthEffectHasItsCandidate) {
  const std::set<std::string> candidates = candidate_names();
  for (const std::string& effect : effect_names())
    EXPECT_TRUE(candidates.count(effect))
        << "truth effect '" << effect << "' has no candidate of that name in montecarlo/records/gap/candidates/";
}

TEST(CandidateRegistry, EveryCandidateIsATruthEffectOrModelLevel) {
  const std::set<std::string> effects = effect_names();
  for (const std::string& candidate : candidate_names())
    EXPECT_TRUE(effects.count(candidate) || kModelLevel.count(candidate))
        << "candidate '" << candidate << "' is neither a truth effect (insmc effects) nor one of the model-level "
        << "candidates bounds, nonlinearity";
}

TEST(CandidateRegistry, NamesAreUnique) {
  EXPECT_EQ(candidate_names().size(), candidate_registry().size());
}

/// Every parameter states its physical limits and why (the maximum-likelihood
/// fit searches between them, docs/gap-method.md §4): a searched one a positive log
/// range that reaches below its grid's least positive value (a grid may
/// reach beyond the upper one: `bounds` to 1000, quantization to 5 m/s, kept
/// for the ranking by G that section 5 validates), an amplitude ± the
/// magnitude its least-squares fit is held at.
TEST(CandidateRegistry, EveryParameterHasPhysicalLimitsWithAReason) {
  for (const Candidate& c : candidate_registry())
    for (const CandidateParameter& p : c.parameters) {
      const std::string where = c.name + "." + p.name;
      EXPECT_FALSE(p.limits.empty()) << where;
      if (p.amplitude) {
        EXPECT_EQ(p.upper_si, p.grid.front()) << where;
        EXPECT_EQ(p.lower_si, -p.upper_si) << where;
        continue;
      }
      EXPECT_GT(p.lower_si, 0.0) << where;
      EXPECT_GT(p.upper_si, p.lower_si) << where;
      for (double v : p.grid) {
        if (v <= 0) continue;  // a grid's 0 (none) is the lower limit's floor
        EXPECT_GE(v, p.lower_si) << where;
      }
    }
}

}  // namespace
}  // namespace insmc::gap
