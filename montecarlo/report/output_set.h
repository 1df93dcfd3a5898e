#pragma once
/// Output folders (`--out DIR`): checked and locked before the work,
/// written as a whole set at the end. docs/outputs.md describes the
/// behaviour for users.
///
/// A set is written into a fresh temporary folder `.<DIR>.insmc-tmp-XXXXXX`
/// beside DIR (files created O_CREAT|O_EXCL|O_NOFOLLOW and fsync'd, the
/// manifest `.insmc-set` last) and then moved in with one rename:
/// - DIR does not exist: renameat2(RENAME_NOREPLACE);
/// - DIR is empty, or holds nothing but a previous set of the same command
///   and files (its manifest says so): renameat2(RENAME_EXCHANGE) swaps
///   the two folders atomically, then the old set is removed.
/// A reader, or a SIGKILL at any moment, sees the old set or the new one.
/// Otherwise DIR holds files that are not insmc's (or another kind of set,
/// or it is the working directory, or a symbolic link to a folder): nothing
/// of the user's is moved or deleted; the manifest is removed first, each
/// file is replaced atomically on its own, and the manifest is written
/// last, so a complete set is one with its manifest.
/// A non-regular file (folder, FIFO, device, socket, symbolic link) at one
/// of the set's names is never replaced: OutputError. Temporaries left by a
/// killed run are removed by the next run on the same DIR (under its lock).
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "montecarlo/report/output_lock.h"

namespace insmc::mc {

/// (file name, contents).
using OutputSetFiles = std::vector<std::pair<std::string, std::string>>;

/// How a set went in (for tests and messages).
enum class SetPlacement { kNew, kExchanged, kInPlace };

class OutputFolder {
 public:
  /// Checks `path` before any work: an existing folder that insmc may write
  /// (write and search permission), or a path whose missing folders can be
  /// created (the nearest existing ancestor is a writable folder); trailing
  /// slashes are fine. Creates the missing parents (not DIR itself, which
  /// appears only with the finished set), takes the lock
  /// (montecarlo/report/output_lock.h) and removes stale temporaries.
  /// `expected_files`: names the set will hold, when known now; a
  /// non-regular file at one of them is refused now. Throws OutputError.
  OutputFolder(const std::string& path, std::string command, const std::vector<std::string>& expected_files = {});

  /// Writes the set as described above; the lock stays held until the
  /// OutputFolder is destroyed. Throws OutputError; a temporary folder is
  /// removed on every failure.
  SetPlacement write(const OutputSetFiles& files);

  const std::filesystem::path& path() const { return target_; }

 private:
  std::filesystem::path target_, parent_;
  std::string name_, command_;
  std::optional<OutputLock> lock_;
};

}  // namespace insmc::mc
