#pragma once
/// The values of the site the diagnosis and its null depend on, each from
/// the records' header when it states them, else inferred from the rows
/// (record_lattice.h, the f spacing), and each said in the report
/// with its source: the null is simulated with them, so an assumption the
/// data do not bear out (the report's 0.1 ft/s pulses on continuous
/// outputs) would show as a gap of its own.
#include <vector>

#include "montecarlo/gap/diagnosis.h"
#include "montecarlo/gap/records/layout.h"

namespace insmc::mc {

/// Fills in the site's pulse weight, position resolution and filter
/// interval where the header leaves them out (`site` as read_site gave
/// it), and returns every value with its source and reason.
std::vector<SiteValue> complete_site(const RecordFile& file, gap::RecordSite& site, const DiagnosisOptions& options);

}  // namespace insmc::mc
