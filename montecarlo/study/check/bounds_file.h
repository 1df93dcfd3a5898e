#pragma once
/// The bounds file of `insmc check --bounds FILE`: one bound a line,
///   scheme=none system=2 axis=horizontal t_min=84 rms_m<=9000 [confidence=0.95]
/// `#` starts a comment. The limit is METRIC_UNIT<=NUMBER or
/// METRIC<=NUMBER UNIT (no space: `cep50<=3nmi`): METRIC rms, or on
/// axis=horizontal cep50, cep95 (= p95, the 95th percentile of the radial
/// error) or 2drms (twice the horizontal RMS); UNIT m, ft or nmi (and km
/// with the number). `confidence=` is a one-sided level in [0.5, 0.999999],
/// the range of --confidence. Every mistake is an
/// InputError whose one-line message starts `FILE:LINE:COLUMN: ` (1-based).
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "lib/common/system.h"
#include "lib/compensation/scheme.h"
#include "montecarlo/report/length_unit.h"
#include "montecarlo/study/model/output_layout.h"

namespace insmc::mc {

/// Caps: a CI job checks tens of bounds (7 schemes × 2 systems × 4 axes × 3
/// report times = 168 covers every output of the report's figures).
/// The file: 1 MiB; a line: 1 KiB (a bound is ~70 bytes).
inline constexpr std::uint64_t kMaxBoundsFileBytes = std::uint64_t{1} << 20;
inline constexpr std::size_t kMaxBoundsLineBytes = 1024;
/// Bounds: 2,000. Distinct report times: 100 (each adds an output per
/// scheme, system and axis to the study, with its histogram; a run's
/// default grid has 49).
inline constexpr std::size_t kMaxBounds = 2'000;
inline constexpr std::size_t kMaxBoundsReportTimes = 100;

/// What a bound limits (docs/outputs.md, "Accuracy metrics").
enum class BoundMetric { kRms, kCep50, kCep95, k2drms };
/// Its key in a bounds file ("rms", "cep50", "p95", "2drms") and the name
/// check prints ("RMS", "CEP50", "CEP95", "2DRMS").
struct BoundMetricNames {
  std::string_view key, label;
};
BoundMetricNames names_of(BoundMetric m);

struct Bound {
  int line = 0;
  Scheme scheme = Scheme::kNone;
  System system = System::kTheodolite;
  Axis axis = Axis::kHorizontal;
  double t_s = 0.0;
  BoundMetric metric = BoundMetric::kRms;
  double limit_m = 0.0;
  LengthUnit unit = LengthUnit::kMetre;  ///< the unit the limit was written in (km as m)
  std::optional<double> confidence;
};

/// Parses the text of a bounds file; `source` names it in messages.
std::vector<Bound> parse_bounds_text(std::string_view text, std::string_view source);

/// Reads (at most kMaxBoundsFileBytes) and parses the file.
std::vector<Bound> read_bounds_file(const std::string& path);

}  // namespace insmc::mc
