#pragma once
/// Truth-level runs as records (docs/records.md): what `insmc simulate` writes,
/// and the null data the gap diagnosis calibrates against. Run `run` of
/// `seed` is a pure function of (seed, run): x from the sampler's stream,
/// the pulse phase from its own stream, the effects' noise from theirs.
#include <cstdint>
#include <optional>
#include <vector>

#include "lib/compensation/truth_compensation.h"
#include "lib/records/record.h"
#include "lib/truth/simulator.h"
#include "montecarlo/study/sampler/sampler.h"

namespace insmc::runs {

/// The effects' normal draws of (seed, run): stream s, counter c → one
/// Philox block → an inverse-CDF normal.
NormalSource philox_normals(std::uint64_t seed, std::uint64_t run);

struct RecordRunSpec {
  double test_duration_s = 900.0;
  double position_resolution_m = 0.0;  ///< r rounded to this (0: not rounded)
  /// The scheme applied after the test run (truth_compensation.h); with any
  /// scheme but none, `setup` is required (its truth options are used).
  Scheme scheme = Scheme::kNone;
  const TruthSchemeSetup* setup = nullptr;
  /// Second switch-over after a realignment (5.1.1, 5.1.2, combined): nav
  /// rows must lie after it; their r is the error of that navigation.
  double nav_start_s = 0.0;
};

/// One simulated run with rows at `times_s` (ascending, > 0): phase test up
/// to T, nav after; f where the filter window is complete; r everywhere.
/// With a scheme, the test rows must be the filter-interval grid τ..T (the
/// data the scheme's estimates use). The effects' processes are realized
/// along each simulated segment from its own switch-over (after a
/// realignment they start again).
RecordRun simulate_record_run(const TruthOptions& truth, const mc::Sampler& sampler, std::uint64_t seed,
                              std::uint64_t run, const std::vector<double>& times_s,
                              const RecordRunSpec& spec);

/// As above with the rows of `pattern` (its test and nav rows): the same
/// times, f components only where the pattern has them.
RecordRun simulate_like(const RecordRun& pattern, const TruthOptions& truth, const mc::Sampler& sampler,
                        std::uint64_t seed, std::uint64_t run, const RecordRunSpec& spec);

/// A file of `runs` runs in insmc's own layout: a row every filter interval
/// through the test run and the navigation (after a realignment, from the
/// second switch-over), every f and r present.
struct OwnFileSpec {
  int runs = 20;
  double test_duration_s = 900.0;
  double nav_duration_s = 90 * 60.0;
  /// r rounded to this and the header's position_resolution_m; nullopt: r
  /// exact and the key absent (the diagnosis then reads the resolution as
  /// unstated, as in a file that does not say).
  std::optional<double> position_resolution_m;
  Scheme scheme = Scheme::kNone;
  const TruthSchemeSetup* setup = nullptr;  ///< required with a scheme (simulate_record_run)
  double realignment_duration_s = 0.0;      ///< with a scheme that realigns
};

/// The file of `spec`, with its truth keys (truth.seed, truth.effect.N):
/// what `insmc simulate` writes in its own layout, and the gap study's own
/// files (without their truth keys).
RecordFile simulate_own_file(const TruthOptions& truth, const mc::Sampler& sampler, std::uint64_t seed,
                             const OwnFileSpec& spec);

}  // namespace insmc::runs
