#pragma once
/// Which effect and how far: the candidates ranked
/// (ranking.h), then the best added greedily while the held-out gap stays
/// significant, each step's shrink measured on held-out runs.
#include "montecarlo/records/gap/diagnosis_options.h"
#include "montecarlo/records/gap/diagnosis_results.h"
#include "montecarlo/records/gap/fit/candidate_fit.h"
#include "montecarlo/records/gap/null/null_calibration.h"
#include "montecarlo/records/gap/ranking/ranking.h"

namespace insmc::gap {

/// The first ranking and the effects the greedy search selects.
struct Selection {
  FirstRanking first;
  std::vector<GreedyStep> greedy;         ///< the effects added, in order
  std::vector<std::string> selected;      ///< their names (the first: the ranking's top, a class "a|b" included)
  std::vector<std::string> statements;    ///< why the search stopped where it did, when not plain
};

/// The candidates ranked on `p`, then added greedily while the gap stays
/// significant. `verdict`: the diagnosis so far (whether the model's gap is
/// significant, its null's critical G and the held-out gap without any
/// candidate).
Selection rank_and_select(const Diagnosis& verdict, const runs::PreparedRuns& p, const ModelNull& null,
                          const DiagnosisOptions& options);

}  // namespace insmc::gap
