#pragma once
/// A strapdown run (lib/imu/strapdown.h) as one run of records
/// (docs/records.md): rows at its output times, phase test for t ≤ T and nav
/// after, f where its filter window is complete, r everywhere. What
/// `insmc import-imu` writes and what the gap diagnosis's null through the
/// import builds, so both follow one convention.
#include <cstdint>

#include "lib/imu/strapdown.h"
#include "lib/records/record.h"

namespace insmc {

RecordRun record_run_of(const StrapdownRun& run, double test_duration_s, std::int64_t id);

}  // namespace insmc
