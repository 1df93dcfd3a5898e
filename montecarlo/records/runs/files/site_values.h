#pragma once
/// The values of the site the diagnosis and its null depend on, each from
/// the records' header when it states them, else inferred from the rows
/// (record_lattice.h, the f spacing), and each said in the report
/// with its source: the null is simulated with them, so an assumption the
/// data do not bear out (the report's 0.1 ft/s pulses on continuous
/// outputs) would show as a gap of its own.
#include <string>
#include <vector>

#include "lib/records/record.h"
#include "montecarlo/records/runs/files/layout.h"
#include "montecarlo/report/json.h"

namespace insmc::runs {

/// A value of the site the null depends on: from the header, inferred from
/// the rows, or the model's default, and why (said in the report).
struct SiteValue {
  std::string key;     ///< header key (dv_pulse_mps, position_resolution_m, filter_interval_s, ...)
  double value = 0;
  std::string source;  ///< "header", "inferred" or "default"
  std::string reason;  ///< one sentence
};


/// Fills in the site's pulse weight, position resolution and filter
/// interval where the header leaves them out (`site` as read_site gave
/// it), and returns every value with its source and reason.
/// `default_pulse_mps`: the pulse weight assumed when the header has none
/// and the f rows are too few to tell a lattice.
std::vector<SiteValue> complete_site(const RecordFile& file, RecordSite& site, double default_pulse_mps);

/// The values as gap.json and compensate.json write them: key → value, source, reason.
mc::Json site_values_json(const std::vector<SiteValue>& values);

}  // namespace insmc::runs
