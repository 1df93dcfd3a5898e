#pragma once
/// Everything that defines a Monte Carlo study, with defaults, units and the
/// validator that checks every constraint (docs/robustness.md lists them).
#include <cstdint>
#include <vector>

#include "lib/common/model_options.h"
#include "lib/common/system.h"
#include "lib/compensation/scheme.h"
#include "lib/preflight/test_run.h"
#include "lib/uncertainty/uncertainty_model.h"
#include "lib/units/physical_range.h"

namespace insmc::mc {

struct StudyConfig {
  std::vector<System> systems = {System::kTheodolite, System::kGyrocompass};
  std::vector<Scheme> schemes = all_schemes();
  /// paper (the report's closed forms), linear (the corrected linear model)
  /// or truth (the nonlinear simulator, per sample, every scheme through its
  /// truth action: docs/truth-vs-models.md).
  Fidelity fidelity = Fidelity::kLinear;
  /// The linear-in-x level that gives the maps and the covariance prediction
  /// (for truth: linear, the reference the truth level is compared with).
  Fidelity map_fidelity() const { return fidelity == Fidelity::kTruth ? Fidelity::kLinear : fidelity; }
  ModelOptions model;
  UncertaintyModel uncertainties;
  /// The preflight test run, its measurements and the realignment (chapter 4, 5).
  TestRunOptions test;
  /// Number of Monte Carlo samples, ≥ 2.
  std::uint64_t samples = 100000;
  /// Seed of the counter-based streams; any 64-bit value.
  std::uint64_t seed = 1;
  /// Worker threads, 0 = all cores. Never changes the results.
  int threads = 0;
  /// Confidence level of the RMS intervals, in (0, 1).
  double confidence = 0.95;
  /// Report times [s] (42, 63, 84 min: ½, ¾ and one Schuler period).
  std::vector<double> report_times_s = {42 * 60.0, 63 * 60.0, 84 * 60.0};
  /// Envelope grid 0..grid_end_s every grid_step_s [s]; step > 0.
  double grid_step_s = 120.0;
  double grid_end_s = 90 * 60.0;
  /// Compute the time grid (envelope_grid.csv) as well as the report times.
  bool with_grid = true;
};

/// 2^40 ≈ 1.1e12 samples (about a week of the linear path on one core): far
/// beyond any study, and block counts and index arithmetic stay exact.
inline constexpr std::uint64_t kMaxSamples = std::uint64_t{1} << 40;
/// Beyond 1 − 1e-6 the interval's quantiles leave double precision for the
/// smallest sample counts; below one half an interval says nothing.
inline constexpr PhysicalRange kConfidenceRange{0.5, 0.999999};
inline constexpr int kMaxThreads = 1024;
/// At most 1800 counting intervals in the study's test run (15 min at
/// 0.5 s, two hours at 4 s; the report counts 90): the engine's per-thread
/// observation products grow with the count (measured: 1.7 GB for 1800
/// intervals, every scheme, 2 threads). Records and simulate have no such
/// product and take any interval the test-run ranges allow.
inline constexpr int kMaxStudyIntervals = 1800;

/// Throws InputError naming the first field that is out of range.
void validate(const StudyConfig& config);

/// Samples per block: fixed, independent of threads and processes, so that
/// block sums and therefore all results are the same bits for any split.
inline constexpr std::uint64_t kBlockSize = 1024;

}  // namespace insmc::mc
