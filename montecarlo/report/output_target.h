#pragma once
/// The checks of an output path made before any work (exit code 2 at once
/// instead of an error after minutes of computing): what the path names,
/// whether it may be written, and its absolute form.
#include <filesystem>
#include <string>

namespace insmc::mc {

struct OutputTarget {
  std::filesystem::path path;  ///< absolute, normalized, without a trailing slash
  bool exists = false;         ///< a folder (or a file, for check_file_target) is there already
};

/// An output folder: an existing writable folder (or a symbolic link to
/// one), or a path whose nearest existing ancestor is a writable folder.
/// Throws OutputError naming what is wrong: empty path, the root, an
/// existing file/FIFO/device, an ancestor that is a file, no permission.
OutputTarget check_folder_target(const std::string& text);

/// An output file (record files, the checkpoint): not a folder or a name
/// ending in '/', not an existing non-regular file (FIFO, device, socket,
/// symbolic link: never replaced), and its folder exists and is writable.
OutputTarget check_file_target(const std::string& text);

}  // namespace insmc::mc
