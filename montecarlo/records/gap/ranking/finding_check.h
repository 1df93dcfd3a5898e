#pragma once
/// The first-ranked finding checked on itself. A candidate is the
/// diagnosis' own approximation of its effect (a random process through
/// knots and bridge modes, a grid searched by least G), so its fitted values
/// need not be unbiased for the effect as `insmc simulate` defines it: files
/// of the records' size and layout are simulated by the truth simulator with
/// the finding's --effect form and fitted exactly as the records were. The
/// mean of the fits over the value simulated is the fit's bias, removed from
/// the value and the 16–84 % range; the bias' own uncertainty (the files'
/// spread over the square root of their number) widens the range.
/// docs/gap-method.md §3.
#include <optional>

#include "lib/records/record.h"
#include "montecarlo/records/gap/diagnosis_options.h"
#include "montecarlo/records/gap/diagnosis_results.h"
#include "montecarlo/records/gap/fit/candidate_fit.h"
#include "montecarlo/records/gap/null/null_calibration.h"

namespace insmc::gap {

/// Files simulated with the finding, per parameter checked.
inline constexpr int kFindingCheckFiles = 6;

/// The first-ranked finding `first` with its parameters and its --effect form
/// corrected by the check; none when it has no --effect form or no
/// parameter to check.
std::optional<CandidateResult> check_finding(const CandidateResult& first, const runs::PreparedRuns& p,
                                             const RecordFile& file, const ModelNull& null,
                                             const DiagnosisOptions& options);

/// A parameter's estimate corrected by its check: value and range shifted
/// by the bias (in the check's coordinate), each side of the range widened
/// by the bias' standard error in quadrature.
ParameterEstimate corrected(const ParameterEstimate& e, const SimulatedCheck& check);

}  // namespace insmc::gap
