#pragma once
/// A fitted candidate as the `--effect` argument `insmc simulate` takes
/// (lib/truth/effect.h): the finding in the effect's own parameterization,
/// so that a user can simulate what the diagnosis found and check it.
#include <string>
#include <vector>

#include "montecarlo/records/gap/diagnosis_results.h"
#include "montecarlo/records/runs/files/layout.h"

namespace insmc::gap {

struct EffectArgument {
  std::string text;               ///< NAME:p=v,...; empty when the candidate is not an effect's
  std::vector<std::string> kept;  ///< the effect's parameters not fitted, at the value written (why)
};

/// The effect of candidate `c` with its fitted values (already in the
/// effect's terms, ranking.cpp) and, for parameters the records do not fit,
/// the effect's defaults or the site's (a transient's warm-up).
EffectArgument effect_argument(const CandidateResult& c, const runs::RecordSite& site);

}  // namespace insmc::gap
