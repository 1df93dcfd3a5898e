#pragma once
/// The output of `insmc compensate` (docs/compensate.md): compensate.md,
/// estimates.csv, compensation.csv, envelope.csv, compensate.json and the
/// figure of each unit's horizontal envelope against the population's.
/// Rendered to strings first, so that nothing is written unless everything
/// was computed.
#include <string>

#include "montecarlo/records/compensate/compensate.h"
#include "montecarlo/report/report.h"

namespace insmc::compensate {

/// compensate's set and stdout: markdown (compensate.md), csv
/// (envelope.csv), json (compensate.json).
mc::ReportOutline compensate_report_outline();

/// The report of `result`; `source`: the record file as the user named it.
mc::Report compensate_report(const CompensateResult& result, const CompensateOptions& options, const std::string& source);

}  // namespace insmc::compensate
