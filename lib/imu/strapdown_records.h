#pragma once
/// A strapdown run (lib/imu/strapdown.h) as one run of records
/// (docs/records.md): rows at its output times, phase test for t ≤ T and nav
/// after, f where its filter window is complete, r everywhere. What
/// `insmc import-imu` writes and what the gap diagnosis's null through the
/// import builds, so both follow one convention.
#include <cstdint>
#include <string>
#include <vector>

#include "lib/imu/imu_samples.h"
#include "lib/imu/strapdown.h"
#include "lib/records/record.h"

namespace insmc {

RecordRun record_run_of(const StrapdownRun& run, double test_duration_s, std::int64_t id);

/// How an input becomes runs: one run from its start (kFile), or
/// consecutive runs of alignment + test run + navigation (kSplit).
enum class RunsFrom { kFile, kSplit };

/// The runs one input makes (at least one: a short input is one run).
int runs_from_input(const ImuSamples& samples, const StrapdownOptions& nav, RunsFrom runs_from);

/// The header of an imported file (lib/records/import_keys.h): the site,
/// test run, pulses none, resolution none, the filter interval, and how the
/// records were made (imu.*). No runs yet.
RecordFile imported_file_header(const StrapdownOptions& nav, const ImuCsvOptions& csv, RunsFrom runs_from);

/// Each input's runs through the strapdown computer, numbered from 0 in the
/// inputs' order, appended to `file` with their imu.run.* header keys
/// (the input's path as given in `sources`, switch time, alignment's gyro
/// bias, roll and pitch).
void append_imported_runs(RecordFile& file, const std::vector<ImuSamples>& inputs,
                          const std::vector<std::string>& sources, const StrapdownOptions& nav, RunsFrom runs_from);

}  // namespace insmc
