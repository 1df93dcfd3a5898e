#pragma once
/// The accuracy columns of envelope.csv and keys of run.json (docs/outputs.md,
/// "Accuracy metrics"): CEP50, CEP95 and 2DRMS in the length unit, the
/// radial error rate in nautical miles per hour, each with `_lo`/`_hi` for
/// its confidence interval (as `rms_lo_m`, `rms_hi_m`). Filled on the rows
/// whose samples were kept (horizontal, at a report time), empty elsewhere.
#include <optional>
#include <string>
#include <vector>

#include "montecarlo/study/aggregate/horizontal_accuracy.h"
#include "montecarlo/report/json.h"
#include "montecarlo/report/length_unit.h"

namespace insmc::mc {

/// m/s to nautical miles per hour.
double mps_to_nmiph(double v_mps);

/// cep50_m, cep50_lo_m, cep50_hi_m, cep95_…, drms2_…, radial_rate_nmiph,
/// radial_rate_lo_nmiph, radial_rate_hi_nmiph (`_ft`, `_nmi` with --units).
std::vector<std::string> accuracy_header(LengthUnit unit);

/// The row's cells for accuracy_header(): full precision, or empty strings
/// without metrics (and for the rate at t = 0, where it is undefined).
std::vector<std::string> accuracy_cells(const std::optional<HorizontalAccuracy>& a, LengthUnit unit);

/// envelope.md's columns: "CEP50 [m]", "CEP95 [m]", "2DRMS [m]",
/// "CEP50/t [n.mi./h]", and a row's cells "value ± half-width"
/// (interval_format.h; half the interval's width), empty without metrics.
std::vector<std::string> readable_accuracy_header(LengthUnit unit);
std::vector<std::string> readable_accuracy_cells(const std::optional<HorizontalAccuracy>& a, LengthUnit unit);

/// The same in SI keys (cep50_m, …, radial_rate_nmiph, …) on a run.json
/// envelope row; null values without metrics.
void add_accuracy_json(Json& row, const std::optional<HorizontalAccuracy>& a);

}  // namespace insmc::mc
