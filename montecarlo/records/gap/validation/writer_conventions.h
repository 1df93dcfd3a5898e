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
#include "montecarlo/study/sampler/sampler.h"

namespace insmc::gap {

/// How simulated records are written (`--layout` of simulate and
/// gap-validate): as insmc writes them, in the foreign writer's conventions,
/// or in conventions drawn by the layout fuzzer.
enum class RecordWriter { kOwn, kForeign, kFuzzed };

struct WriterConventions {
  double f_every_s = 10.0, r_every_s = 30.0;
  bool pulses = true;    ///< f counted in 0.1 ft/s pulses (else continuous)
  bool zero_row = false; ///< a row at t = 0 (r only)
  // What the layout fuzzer draws besides (fuzzed_conventions_of); the defaults
  // are the foreign writer's fixed conventions.
  /// Each run loses a share of its f records and of its rows, drawn in
  /// [0, dropout_max] for the run, at times of its own (a logger dropping
  /// samples; r is on every row, so a lost r sample is a lost row).
  double dropout_max = 0.0;
  bool f_in_nav = true;          ///< f recorded after the test run too
  double resolution_m = -1.0;    ///< r rounded to this (< 0: ForeignRuns::position_resolution_m)
  /// Share of the runs that stop early: at 60-80 min into the navigation
  /// (every third run, short_from_s < 0), or each with probability
  /// short_share at a time drawn in [short_from_s, the end].
  double short_share = 1.0 / 3.0;
  double short_from_s = -1.0;
  bool header_keys = false;      ///< dv_pulse_mps, filter_interval_s and position_resolution_m written
  std::string describe() const;
};

/// The layout of the file of `file_seed`: every combination comes round.
/// A file of an effect on the pulse counting (EffectInfo::needs_pulses)
/// keeps the pulses its effect is about.
WriterConventions foreign_conventions_of(std::uint64_t file_seed, bool needs_pulses);

/// The layout fuzzer: conventions drawn at random from the file's seed, not
/// from a fixed set, so that no assumption of a writer the team made is
/// built in: f and r every 1-60 s (whole seconds, each its own), each run's
/// own dropouts of 0-10 %, f absent after the test run or not, r resolution
/// 0.1 mm to 3 ft or exact, pulses or continuous f, short runs stopping
/// anywhere from half the test run on, the optional header keys written or
/// not. `test_duration_s` places the short runs' stops.
WriterConventions fuzzed_conventions_of(std::uint64_t file_seed, bool needs_pulses, double test_duration_s);

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
                                 const WriterConventions& conventions);

}  // namespace insmc::gap
