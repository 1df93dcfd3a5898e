#pragma once
/// The rows of r the model does not read, screened against those it reads.
/// The model reads r one row per slot (30 s in the test run, 60 s after:
/// runs::ExtractionOptions; r is smooth and the model's cost grows with its
/// rows), so a corrupt value between two read rows would go unseen by the
/// residuals and their outlier test (outliers.h).
///
/// Each unread row is compared with the straight line through the read rows
/// on either side (t_a < t < t_b). A smooth error of acceleration at most a
/// leaves that line by at most a (t − t_a)(t_b − t)/2, and a resolution q
/// moves each of the three values by at most q/2, so the line by at most q.
/// a is taken as the largest second difference of the read rows at t_a and
/// t_b (their own quantization only widens it; a turn between read rows
/// escapes it). A row is beyond when it leaves the line by more than ten
/// times that reach: a corrupt value, not the model's smooth error.
#include <string>
#include <vector>

#include "lib/records/record.h"
#include "montecarlo/records/gap/diagnosis_results.h"
#include "montecarlo/records/runs/files/layout.h"

namespace insmc::gap {

/// `file`'s r rows against the rows `runs` read (matched by run number and
/// time); `resolution_m` the position computer's (0: continuous).
UnreadRows screen_unread_rows(const RecordFile& file, const std::vector<runs::RunData>& runs, double resolution_m);

/// Beyond the bound in at most a tenth of the runs (at least one): a
/// record of its own, said first (as outliers.h's).
bool unread_rows_isolated(const UnreadRows& u);

/// "r is read one row per 30 s ...: N of M rows ..." or "" when every row is read.
std::string unread_rows_sentence(const UnreadRows& u);

/// "An r value of one run that the model does not read leaves ...: a
/// corrupt record." or "" unless isolated: said first (as outliers_sentence).
std::string unread_rows_finding(const UnreadRows& u);

}  // namespace insmc::gap
