#pragma once
/// Which effect: every candidate fitted on one half of the runs
/// and scored on the other (2-fold cross-validation), ranked by held-out G;
/// each candidate's shrink on null files as the reference of its shrink on
/// the records.
#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "montecarlo/records/gap/diagnosis_options.h"
#include "montecarlo/records/gap/diagnosis_results.h"
#include "montecarlo/records/gap/fit/candidate_fit.h"
#include "montecarlo/records/gap/null/null_calibration.h"

namespace insmc::gap {

struct Scored {
  int candidate = 0;
  double heldout_gap = 0;
  RunSet heldout;  // every run at the other half's fit
  Choice full_fit;
  std::array<Choice, 2> half_fit;  ///< fitted on half h (runs h, h + 2, …)
  std::vector<ParameterEstimate> parameters;
};

/// The choices of least G on each half of n runs (half h: runs h, h + 2, …).
std::array<Choice, 2> half_fits(const CandidateSums& s, std::size_t n, const NullCalibration& m0);

/// How many null files of the records' size the null calibration holds, up
/// to options.null_shrink_files, and null file f: p with its runs replaced
/// by consecutive runs of the null calibration.
int null_file_count(const runs::PreparedRuns& p, const ModelNull& null, const DiagnosisOptions& options);
runs::PreparedRuns null_file(const runs::PreparedRuns& p, const ModelNull& null, int f);

/// Every candidate not in `exclude`, on top of the effects `selected` (per
/// layout), scored; ascending held-out gap (registry order among equals).
/// With `with_null_shrinks` (before any effect is selected) also each
/// candidate's held-out shrink on options.null_shrink_files null files of
/// the records' size (consecutive runs of the null calibration, split and
/// fitted as the records are), the median over the files: what fitting the
/// candidate gains on noise alone, the reference its shrink on the records
/// is read against. The null files are evaluated with the records (their
/// layouts' models built once for both), each searched on its own.
struct RankedCandidates {
  std::vector<Scored> ranked;
  std::vector<double> null_shrink;  ///< per registry entry; NaN where not measured
};
RankedCandidates rank_candidates(const runs::PreparedRuns& p, const std::vector<std::vector<runs::Extension>>& selected,
                                 const std::vector<std::string>& exclude, const ModelNull& null,
                                 const DiagnosisOptions& options, std::string_view stage, bool with_null_shrinks);

/// Every candidate's result of `candidates.ranked` (not empty) with its null shrink and
/// its likelihood side, and the top one (a class "a|b" when the runner-up
/// is within two resampling standard errors). `before`: the held-out gap
/// without any candidate.
FirstRanking first_ranking(const RankedCandidates& candidates, const runs::PreparedRuns& p, const ModelNull& null,
                           const DiagnosisOptions& options, double before);

}  // namespace insmc::gap
