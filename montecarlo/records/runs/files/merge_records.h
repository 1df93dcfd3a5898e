#pragma once
/// Record files of one site read as one (`insmc gap --records A --records B`).
#include <string>
#include <vector>

#include "lib/records/record.h"

namespace insmc::runs {

/// Merges several record files of the same site (latitude, system, T,
/// scheme) into one; runs are renumbered if their numbers collide. Throws
/// InputError naming the file whose header differs, or that holds the same
/// runs as another (the same file twice, or a copy).
RecordFile merge_record_files(const std::vector<RecordFile>& files, const std::vector<std::string>& names);

}  // namespace insmc::runs
