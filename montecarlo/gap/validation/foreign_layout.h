#pragma once
/// Validation records in another recorder's conventions (docs/gap-method.md §5,
/// "Foreign layouts"): the same truth-level runs as gap-validate's own
/// files, written as software other than insmc would write them — f every
/// 5, 10 or 20 s and r every 10, 30 or 60 s on their own grids (rows with
/// r and empty f cells), a row at t = 0 in some files, a third of the runs
/// stopping 60-80 min into the navigation, run numbers that are not
/// consecutive, unknown header keys, no dv_pulse_mps or filter_interval_s
/// key (continuous or 0.1 ft/s outputs, to be inferred), numbers to 9
/// significant digits. The diagnosis must take them as they come.
#include <cstdint>
#include <string>
#include <vector>

#include "lib/records/record.h"
#include "lib/truth/simulator.h"
#include "montecarlo/sampler/sampler.h"

namespace insmc::gap {

struct ForeignLayout {
  double f_every_s = 10.0, r_every_s = 30.0;
  bool pulses = true;    ///< f counted in 0.1 ft/s pulses (else continuous)
  bool zero_row = false; ///< a row at t = 0 (r only)
  std::string describe() const;
};

/// The layout of the file of `file_seed`: every combination comes round.
/// A file of an effect on the pulse counting (EffectInfo::needs_pulses)
/// keeps the pulses its effect is about.
ForeignLayout foreign_layout_of(std::uint64_t file_seed, bool needs_pulses);

/// `runs` truth-level runs (scheme none) of `truth` (its effects, site and
/// system; its filter interval and pulse weight are the layout's), run r a
/// pure function of (seed, r) as in the own files, in `layout`, without
/// truth keys. r rounded to `position_resolution_m` (0: exact); the header
/// names neither.
struct ForeignRuns {
  double test_duration_s = 900.0, nav_duration_s = 5400.0, position_resolution_m = 0.0;
  int runs = 20;
};
RecordFile simulate_foreign_file(TruthOptions truth, const mc::Sampler& sampler, std::uint64_t seed, const ForeignRuns& runs,
                                 const ForeignLayout& layout);

}  // namespace insmc::gap
