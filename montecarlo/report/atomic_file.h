#pragma once
/// Writing one output file so that a reader sees the old file or the new
/// one, never a half-written or foreign one. The primitives here also serve
/// the output sets (montecarlo/report/output_set.h).
///
/// Temporaries are named `.<name>.insmc-tmp-XXXXXX` (six random letters or
/// digits) beside their target, created with O_CREAT|O_EXCL|O_NOFOLLOW (a
/// planted file or symbolic link at that name is never opened), flushed
/// with fsync, renamed over the target and the folder fsync'd. A temporary
/// left by a killed process is recognisable by that name;
/// remove_stale_temporaries() clears them for a target whose lock is held.
#include <sys/types.h>

#include <filesystem>
#include <string>
#include <string_view>

namespace insmc::mc {

/// "a folder", "a FIFO", "a device", "a symbolic link", "a socket", "a file".
std::string describe_file_type(mode_t mode);

/// `.<name>.insmc-tmp-XXXXXX` with fresh random letters.
std::string temporary_name(std::string_view name);
/// Whether `entry` has the form temporary_name(name) gives.
bool is_temporary_of(std::string_view entry, std::string_view name);

/// Removes the temporaries of `name` (files, or folders of a set) in the
/// folder `dir_fd` (its path `dir` for messages). Only for a target whose
/// lock (montecarlo/report/output_lock.h) the caller holds: no live writer
/// then owns such a name.
void remove_stale_temporaries(int dir_fd, const std::filesystem::path& dir, std::string_view name);

/// Creates `name` in the folder `dir_fd` with O_CREAT|O_EXCL|O_NOFOLLOW,
/// writes `contents` and fsyncs it. Throws OutputError (nothing is left
/// behind) when the name exists or a step fails.
void write_new_file(int dir_fd, const std::filesystem::path& dir, const std::string& name,
                    std::string_view contents);

/// Replaces (or creates) the regular file `name` in the folder `dir_fd`
/// atomically through a temporary beside it, then fsyncs the folder.
/// Refuses (OutputError) when `name` exists and is not a regular file (a
/// folder, FIFO, device, socket or symbolic link is never replaced).
void replace_file_at(int dir_fd, const std::filesystem::path& dir, const std::string& name,
                     std::string_view contents);

/// replace_file_at() in the folder of `path`. On any failure `path` is left
/// as it was, no temporary remains, and OutputError (a std::runtime_error)
/// names the path and the system error.
void write_file_atomically(const std::filesystem::path& path, std::string_view contents);

}  // namespace insmc::mc
