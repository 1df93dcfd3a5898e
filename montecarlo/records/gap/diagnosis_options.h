#pragma once
/// What a diagnosis is asked to do (`insmc gap`, docs/gap.md): the options
/// every stage reads. The records are read with the run model's options
/// (runs/prepared_runs.h) this extends.
#include <cstdint>
#include <functional>
#include <memory>
#include <string_view>
#include <vector>

#include "montecarlo/records/gap/candidates/candidates.h"
#include "montecarlo/records/runs/prepared_runs.h"

namespace insmc::gap {

/// Where a long diagnosis is: its stage, the count done of the stage's total
/// and what is counted (called from worker threads, in any order).
using DiagnosisProgress =
    std::function<void(std::string_view stage, std::uint64_t done, std::uint64_t total, std::string_view unit)>;

/// When candidate effects are fitted and ranked.
enum class RankWhen {
  kAlways,         ///< always (the ranking of a null file shows what fitting noise gains)
  kIfSignificant,  ///< only when there is a significant unmodelled gap
  kNever,          ///< never: the gap, its significance and where it lies only (screening)
};

/// Runs of one diagnosis, over all its record files: it simulates
/// max(200, 10 × runs) null runs and keeps them, so its memory grows with
/// the runs (measured with one-row runs: 200 runs peak at 0.7 GB and take
/// 7 min; 1,000 runs passed 9 GB and still grew); a test campaign records
/// tens. import-imu writes no more.
inline constexpr std::size_t kMaxDiagnosedRuns = 200;

struct DiagnosisOptions : runs::RecordReading {
  double alpha = 0.01;              ///< false-alarm rate of "significant"
  std::uint64_t seed = 1;           ///< null runs and resampling
  int calibration_runs = 0;         ///< null runs; 0: max(200, 10 × runs)
  int bootstrap = 2000;             ///< null files for the p-values
  int max_selected = 3;             ///< greedy additions at most
  int minimum_runs = 5;             ///< for a ranking (two halves of ≥ 2 runs)
  /// Null files (of the records' size, from the calibration runs) on which
  /// each candidate's held-out shrink is measured as the reference of its
  /// shrink on the records (CandidateResult::null_shrink); 0: not measured.
  int null_shrink_files = 3;
  /// Candidates (the best by held-out G) also fitted by maximum likelihood
  /// between physical limits, and how many of them are paired; 0: none.
  /// Off unless asked for (`gap --likelihood N`): the likelihood of the run
  /// model is not yet calibrated on the null as G is, and it costs 2-3 times
  /// the rest of the diagnosis (docs/gap-method.md §4).
  int likelihood_candidates = 0;
  int likelihood_pair_candidates = 0;
  RankWhen rank = RankWhen::kAlways;
  DiagnosisProgress progress;  ///< may be empty
  /// The candidates to rank; empty: the registry's. diagnose() sets it to the
  /// registry limited by the raw-sensor stage when the records carry one
  /// (records/raw_stage.h).
  std::shared_ptr<const std::vector<Candidate>> candidates;
};

/// Checks every setting's range; throws InputError naming the option of
/// `insmc gap` that sets it.
void validate(const DiagnosisOptions& options);

/// The smallest false-alarm rate allowed: the null files' tail beyond it
/// would rest on a few of the calibration runs.
inline constexpr double kMinAlpha = 1e-4;

/// Null files for p-values at `alpha`: the default 2,000, or enough that
/// the least p-value they can give, 1/(files + 1), is a tenth of alpha (at
/// alpha 1e-4 with 2,000, p could never fall below alpha and no gap would
/// ever be significant).
int null_files_for(double alpha);

/// options.candidates, or the registry's.
inline const std::vector<Candidate>& candidates_of(const DiagnosisOptions& options) {
  return options.candidates ? *options.candidates : candidate_registry();
}

/// Calls options.progress when it is set.
inline void report_progress(const DiagnosisOptions& options, std::string_view stage, std::uint64_t done,
                            std::uint64_t total, std::string_view unit) {
  if (options.progress) options.progress(stage, done, total, unit);
}

}  // namespace insmc::gap
