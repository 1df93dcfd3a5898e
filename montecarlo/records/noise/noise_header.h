#pragma once
/// The import's raw-sensor stage (`insmc import-imu --noise on`): the noise
/// terms fitted on the inputs (lib/noise/, docs/noise.md) kept in the
/// record header under imu.noise.* (lib/records/import_keys.h), where the
/// gap diagnosis reads the unit's own noise.
#include <vector>

#include "lib/imu/imu_samples.h"
#include "lib/records/record.h"

namespace insmc::noise {

/// The raw-sensor stage on `samples` (docs/noise.md), its fitted terms kept
/// in the header as imu.noise.<channel>.<term>_si (with _lower_si,
/// _upper_si), .equivalent_si (the terms as a constant error over one
/// Schuler period) and .warm_up_excluded; imu.noise = "skipped: ..." when the
/// inputs cannot be analysed (too short, not on one sample grid).
void write_noise_header(const std::vector<ImuSamples>& samples, RecordHeader& header);

}  // namespace insmc::noise
