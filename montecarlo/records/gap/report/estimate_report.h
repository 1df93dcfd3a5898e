#pragma once
/// The test of the per-run estimates against the prior
/// (where/estimate_test.h) in gap.json (`gap.estimates`) and gap.md: a row
/// per estimate with each statistic, its null critical value and p, and the
/// candidates scored on the estimates (ranking/estimate_naming.h).
#include <string>

#include "montecarlo/records/gap/diagnosis.h"
#include "montecarlo/report/json.h"

namespace insmc::gap {

mc::Json estimate_test_json(const EstimateTest& t);

/// gap.md's subsection (empty when the test was not made).
std::string estimate_test_markdown(const EstimateTest& t, double alpha);

}  // namespace insmc::gap
