#pragma once
/// The null through the import (docs/gap-method.md §2). Records that came through
/// `import-imu` with its raw-sensor stage state the sensor's fitted noise
/// (header imu.noise.*, docs/noise.md) and how they were imported (imu.*).
/// The null runs then carry that noise too: it is synthesized at the raw
/// sample interval (lib/noise/noise_synthesis.h) on the exact outputs of a
/// stationary sensor at the site, turned as the run's sensor was, and
/// passed through the importer's own path (leveling and gyro-bias estimate
/// over its alignment window, strapdown, the same output rows). So the
/// alignment's own bias-estimate error (about N/√T_align of each gyro) and
/// the importer's conventions are part of what the null expects, and a
/// sensor whose navigation errors are what its raw noise makes of them is
/// not an unmodelled effect.
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "lib/imu/strapdown.h"
#include "lib/noise/noise_fit.h"
#include "lib/records/record.h"

namespace insmc::gap {

struct ImportNull {
  StrapdownOptions nav;                      ///< the importer's settings (imu.* keys)
  std::array<noise::NoiseModel, 6> channels; ///< gyro x, y, z, accel x, y, z
  double sample_interval_s = 0.1;            ///< of the synthesized samples
  std::string description;                   ///< one line for the report
};

/// From the file's header; nullopt (with a statement saying why) when the
/// records did not come through import-imu with its noise stage, when its
/// keys cannot be used (missing, or a value outside its physical range), or
/// when a row is not one of the import's output times.
std::optional<ImportNull> import_null_for(const RecordFile& file, std::vector<std::string>& statements);

/// Adds the synthesized noise of null run `run` of `seed`, through the
/// import, to `null_run`'s rows (its r, and f where both have it), the
/// sensor turned as the records' run `pattern_id` was (imu.run<id>.roll_deg,
/// pitch_deg; level when absent). Every row of `null_run` must be one of the
/// import's output times (the records' own rows are).
void add_import_noise(RecordRun& null_run, const RecordHeader& header, std::int64_t pattern_id,
                      const ImportNull& import, std::uint64_t seed, std::uint64_t run);

}  // namespace insmc::gap
