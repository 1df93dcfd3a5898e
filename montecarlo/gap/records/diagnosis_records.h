#pragma once
/// Records in: the record file as the diagnosis uses it (its site
/// completed, short filter windows summed, a scheme's estimates recomputed
/// from each run's own test rows) and its runs extracted onto their layouts.
#include <string>
#include <vector>

#include "montecarlo/gap/diagnosis.h"
#include "montecarlo/gap/fit/candidate_fit.h"
#include "montecarlo/gap/model/scheme_rows.h"

namespace insmc::mc {

/// The records as the diagnosis uses them, and its site. After a scheme
/// that uses the test run, each run's estimates are recomputed from its test
/// rows (scheme_rows.h): the test rows kept are the filter grid τ..T the
/// estimates use; when a run lacks part of that grid, the navigation rows
/// cannot be conditioned on the estimates and only the test run (still
/// uncompensated) is diagnosed.
struct Records {
  RecordFile file;
  gap::RecordSite site;
  std::vector<gap::SchemeEstimates> estimates;  // per run, for a scheme that uses the test run
  bool navigation_dropped = false;              // the scheme's estimates could not be recomputed
};

/// The report's estimators of the records' test run (T, τ, pulse weight and
/// resolution from the completed site), with the terms `insmc run` fits
/// (resolvable_terms under `prior`); throws InputError naming the header key
/// of a test-run setting out of range.
TestRunEstimators record_estimators(const gap::RecordSite& site, const UncertaintyModel& prior);

Records records_for_diagnosis(const RecordFile& file, const DiagnosisOptions& options,
                              std::vector<std::string>& statements, std::vector<SiteValue>& site_values);

/// Takes the scheme's use of a run's own test-run estimates off its rows
/// (scheme_rows.h): exact, whatever moved the estimates.
void take_off_estimates(gap::RunData& run, const gap::BaseModel& base, const gap::SchemeEstimates& estimates);

/// The records' runs on their layouts, each layout with its base model, the
/// scheme's estimates taken off.
PreparedRuns prepare(const Records& records, const DiagnosisOptions& options);

}  // namespace insmc::mc
