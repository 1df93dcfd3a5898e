#pragma once
/// The error of the output writers (montecarlo/report/atomic_file.h,
/// output_lock.h, output_set.h): what could not be done to which path and
/// why. Almost every cause is one the user can fix (permissions, a full or
/// read-only file system, a file where a folder is wanted, another insmc
/// holding the lock); the programs turn those into exit code 2
/// (apps/output_paths.h) and keep exit code 3 for defects.
#include <filesystem>
#include <stdexcept>
#include <string>

namespace insmc::mc {

class OutputError : public std::runtime_error {
 public:
  /// `problem`: one line without the path (e.g. "is a FIFO, not a folder").
  /// `error`: the errno behind it, 0 when it is not a system error.
  OutputError(std::filesystem::path path, std::string problem, int error = 0);

  const std::filesystem::path& path() const { return path_; }
  /// The problem alone, without the path (for messages that name the path
  /// themselves: "--out = DIR: <problem>").
  const std::string& problem() const { return problem_; }
  int error() const { return error_; }
  /// False for the errno values that only a defect of insmc can cause
  /// (EBADF, EFAULT, EINVAL): exit code 3 rather than 2.
  bool user_fixable() const;

 private:
  std::filesystem::path path_;
  std::string problem_;
  int error_;
};

/// Throws OutputError(path, step + ": " + strerror(error), error).
[[noreturn]] void throw_system_error(const std::filesystem::path& path, const std::string& step, int error);

}  // namespace insmc::mc
