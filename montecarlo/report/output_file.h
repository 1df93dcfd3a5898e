#pragma once
/// A single output file (`simulate --out FILE`, `import-imu --out FILE`,
/// `run --checkpoint FILE`): checked (montecarlo/report/output_target.h) and
/// locked (montecarlo/report/output_lock.h) before the work, written
/// atomically (montecarlo/report/atomic_file.h) as often as needed.
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "montecarlo/report/output_lock.h"

namespace insmc::mc {

class OutputFile {
 public:
  /// Throws OutputError: see check_file_target(); another process holds
  /// the lock. Removes the temporaries a killed writer left beside it.
  explicit OutputFile(const std::string& path);

  /// Replaces the file atomically; throws OutputError (the old file stays).
  void write(std::string_view contents) const;

  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
  std::optional<OutputLock> lock_;
};

}  // namespace insmc::mc
