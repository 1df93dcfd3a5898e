// Every effect of the truth simulator (lib/truth/effects/, the names
// `insmc effects` prints) has its candidate of the same name in the
// diagnosis (montecarlo/gap/candidates/): an effect without one could be
// simulated and withheld by gap-validate but never named by the diagnosis.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "lib/truth/effect.h"
#include "montecarlo/gap/candidates/candidates.h"

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
        << "truth effect '" << effect << "' has no candidate of that name in montecarlo/gap/candidates/";
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

}  // namespace
}  // namespace insmc::gap
