#pragma once
/// After the ranking and greedy steps: their limits, in the report's words.
#include <string>
#include <vector>

#include "montecarlo/records/gap/diagnosis_results.h"

namespace insmc::gap {

/// What the ranking cannot support, said plainly (docs/gap.md: priors too narrow,
/// effect not identifiable, disturbances masked): statements the report adds.
std::vector<std::string> ranking_limits(const Diagnosis& d);

/// The tests that would separate candidates a and b, from each one's
/// told_apart_by (candidates/candidates.h), in one clause.
std::string what_tells_apart(const std::string& a, const std::string& b);

}  // namespace insmc::gap
