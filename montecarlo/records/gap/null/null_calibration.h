#pragma once
/// The model's own null: truth-level runs like the records' (no
/// effect, the priors), under the base model, calibrating the metric
/// (metric/gap_metric.h) and giving the null files every p-value is read
/// against.
#include <Eigen/Dense>
#include <cstdint>
#include <vector>

#include "lib/records/record.h"
#include "lib/truth/effect.h"
#include "montecarlo/records/gap/diagnosis_options.h"
#include "montecarlo/records/gap/metric/run_set.h"
#include "montecarlo/records/runs/prepared_runs.h"
#include "montecarlo/records/gap/metric/gap_metric.h"
#include "montecarlo/records/gap/null/import_null.h"

namespace insmc::gap {

/// Everything the candidate search needs from the null calibration.
struct ModelNull {
  NullCalibration calibration;        // κ_g, λ_c
  std::vector<double> gaps;                // G of the null files
  std::vector<double> unmodelled;          // G₊ of the null files
  std::vector<double> pessimistic;         // G₋ of the null files
  std::vector<LogRatios> log_ratios;  // ℓ of the null files
  RunSet set;                         // the null runs under the base model
  std::vector<runs::RunData> runs;          // the null runs (estimates taken off)
  std::vector<int> layout_of;              // their layouts
};

/// `runs` truth runs like the records' (their times and f rows, run j on
/// the pattern of record j mod their count), as the diagnosis reads them
/// (estimates taken off), placed in p's layouts (into layout_of). Run j is
/// run first_run + j of options.seed's streams; `effects` are added to the
/// model (none: the null); with `import`, the sensor's noise through the
/// import is added to each.
std::vector<runs::RunData> simulate_like_records(runs::PreparedRuns& p, const RecordFile& file, const DiagnosisOptions& options,
                                                int runs, std::uint64_t first_run, const std::vector<EffectSpec>& effects,
                                                std::vector<int>& layout_of, const ImportNull* import = nullptr);

/// What the null calibration may hold: its runs keep their observations
/// (each run's values, the layout it is placed in, its keyed and analysed
/// values) until the candidates are ranked, so `runs` null runs like the
/// records' hold runs × (the records' mean observations a run) of them.
/// Measured (docs/robustness.md, "Work budgets"): 55 bytes an observation
/// (6 runs of 1173 observations: 30 MB at 200 null runs, 127 MB at 1700),
/// and 2.8 ms a null run to simulate; 64 bytes are counted, and 0.8 GB of
/// them bound the calibration (10,600 null runs of these records, 30 s).
inline constexpr double kNullBytesPerObservation = 64.0;
inline constexpr double kMaxNullBytes = 0.8e9;

/// Throws InputError naming --calibration-runs (`automatic`: the default
/// max(200, 10 × runs)) when `nulls` calibrations (2 when the null through
/// the import is held beside the model's) of `runs` null runs like p's runs
/// exceed the budget above, with the largest count that fits; before any
/// null run is simulated.
void check_null_budget(const runs::PreparedRuns& p, int runs, bool automatic, int nulls);

/// The model's own null: truth runs like the records' (their times, f rows,
/// site, pulses), their run set under the base model, the calibration, and
/// the G of 2000 bootstrap files of the records' size. `z` and `layout_of`
/// keep each null run's row values and layout (for the Allan curves).
/// With `import`, every null run also carries the sensor's noise through
/// the import (null/import_null.h).
ModelNull calibrate(runs::PreparedRuns& p, const RecordFile& file, const DiagnosisOptions& options, int runs,
               std::vector<Eigen::VectorXd>& z, std::vector<int>& layout_of, const ImportNull* import = nullptr);

/// ℓ of options.bootstrap null files of `file_runs` runs drawn from `set`
/// (options.seed's resampling streams, as calibrate draws them), against
/// `calibration`: the null files of one null read with another's
/// expectations (the sensor's own noise on the model's scale).
std::vector<LogRatios> null_file_log_ratios(const RunSet& set, const NullCalibration& calibration,
                                            const DiagnosisOptions& options, int file_runs);

}  // namespace insmc::gap
