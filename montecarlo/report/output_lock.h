#pragma once
/// The lock that lets one insmc at a time write an output (a folder set or
/// a file): flock(LOCK_EX | LOCK_NB) on `.<name>.insmc-lock` beside the
/// target, taken before the work starts and held until the output is in
/// place. A second insmc is refused at once (OutputError, exit code 2)
/// instead of racing the first. The kernel drops a flock when its holder
/// dies, so a killed run never blocks the next; the lock file itself is
/// removed on release (a left-over one from a killed run is simply taken).
#include <filesystem>
#include <string>

#include "montecarlo/report/unique_fd.h"

namespace insmc::mc {

class OutputLock {
 public:
  /// Locks `.<name>.insmc-lock` in the folder `dir`, both taken from what
  /// `dir/name` resolves to, so that aliases of one output (a symbolic link
  /// to it, a path through a linked parent) take the same lock. When that folder
  /// cannot take a new file (read-only or not ours) but `dir/name` is an
  /// existing folder, that folder itself is flocked instead (it is then
  /// written file by file in place, never swapped, so its inode stays).
  /// Throws OutputError when another process holds the lock.
  OutputLock(const std::filesystem::path& dir, const std::string& name);
  OutputLock(OutputLock&&) noexcept = default;
  OutputLock& operator=(OutputLock&&) noexcept = default;
  OutputLock(const OutputLock&) = delete;
  OutputLock& operator=(const OutputLock&) = delete;
  /// Removes the lock file (while still holding it), then unlocks.
  ~OutputLock();

  /// The lock file, empty when the target folder itself is locked.
  const std::filesystem::path& lock_file() const { return lock_file_; }

 private:
  std::filesystem::path lock_file_;
  UniqueFd fd_;
};

}  // namespace insmc::mc
