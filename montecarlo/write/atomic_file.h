#pragma once
/// Writing output files so that a reader never sees a half-written file.
#include <filesystem>
#include <string_view>

namespace insmc::mc {

/// Writes `contents` to `path` atomically: the bytes go to `path` + ".tmp"
/// in the same directory, which is flushed to disk (fsync) and closed, with
/// every step checked, and then renamed over `path` (rename(2) is atomic
/// within one file system). An existing file at `path` is replaced.
/// On any failure the temporary file is removed, `path` is left as it was,
/// and std::runtime_error is thrown with a message naming the path and the
/// system error.
void write_file_atomically(const std::filesystem::path& path, std::string_view contents);

}  // namespace insmc::mc
