#include "montecarlo/report/output_set.h"

#include <dirent.h>
#include <fcntl.h>
#include <stdio.h>  // renameat2 (glibc >= 2.28, _GNU_SOURCE)
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <set>
#include <string_view>
#include <system_error>

#include "montecarlo/report/atomic_file.h"
#include "montecarlo/report/output_error.h"
#include "montecarlo/report/output_manifest.h"
#include "montecarlo/report/output_target.h"
#include "montecarlo/report/unique_fd.h"

namespace insmc::mc {

namespace {

namespace fs = std::filesystem;

UniqueFd open_folder(const fs::path& path, int at = AT_FDCWD, const char* name = nullptr, bool follow = true) {
  const int flags = O_RDONLY | O_DIRECTORY | O_CLOEXEC | (follow ? 0 : O_NOFOLLOW);
  UniqueFd fd(::openat(at, name != nullptr ? name : path.c_str(), flags));
  if (!fd.valid()) throw_system_error(path, "open the folder", errno);
  return fd;
}

/// The entries of a folder, without "." and "..".
std::vector<std::string> list_folder(int dir_fd, const fs::path& path) {
  const int fd = ::openat(dir_fd, ".", O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) throw_system_error(path, "open the folder", errno);
  DIR* d = ::fdopendir(fd);
  if (d == nullptr) {
    const int error = errno;
    ::close(fd);
    throw_system_error(path, "list the folder", error);
  }
  std::vector<std::string> names;
  while (const dirent* e = ::readdir(d)) {
    const std::string_view n = e->d_name;
    if (n != "." && n != "..") names.emplace_back(n);
  }
  ::closedir(d);
  return names;
}

bool is_regular_file_at(int dir_fd, const std::string& name) {
  struct stat st {};
  return ::fstatat(dir_fd, name.c_str(), &st, AT_SYMLINK_NOFOLLOW) == 0 && S_ISREG(st.st_mode);
}

std::optional<OutputManifest> read_manifest(int dir_fd) {
  UniqueFd fd(::openat(dir_fd, std::string(kManifestName).c_str(), O_RDONLY | O_NOFOLLOW | O_CLOEXEC));
  if (!fd.valid()) return std::nullopt;
  struct stat st {};
  if (::fstat(fd.get(), &st) != 0 || !S_ISREG(st.st_mode) || st.st_size > (1 << 20)) return std::nullopt;
  std::string text(static_cast<std::size_t>(st.st_size), '\0');
  std::size_t got = 0;
  while (got < text.size()) {
    const ssize_t n = ::read(fd.get(), text.data() + got, text.size() - got);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return std::nullopt;
    got += static_cast<std::size_t>(n);
  }
  return parse_manifest(text);
}

/// Whether the folder holds nothing but a set with exactly these files
/// (and its manifest), all regular files; or nothing at all.
bool holds_only_a_set_like(int dir_fd, const fs::path& path, const OutputManifest& wanted) {
  const std::vector<std::string> entries = list_folder(dir_fd, path);
  if (entries.empty()) return true;
  const std::optional<OutputManifest> old = read_manifest(dir_fd);
  if (!old || old->command != wanted.command || old->files != wanted.files) return false;
  for (const std::string& e : entries) {
    const bool listed = e == kManifestName || std::binary_search(old->files.begin(), old->files.end(), e);
    if (!listed || !is_regular_file_at(dir_fd, e)) return false;
  }
  return true;
}

bool same_file(const fs::path& a, const fs::path& b) {
  struct stat sa {}, sb {};
  return ::stat(a.c_str(), &sa) == 0 && ::stat(b.c_str(), &sb) == 0 && sa.st_dev == sb.st_dev &&
         sa.st_ino == sb.st_ino;
}

mode_t default_folder_mode() {
  const mode_t mask = ::umask(0);
  ::umask(mask);
  return 0777 & ~mask;
}

/// A temporary folder beside the target holding the whole set. The
/// destructor removes whatever is at its name then: the set itself after a
/// failure, nothing after a move to a new target, the old set after a swap.
class TempSet {
 public:
  TempSet(int parent_fd, const fs::path& parent, const std::string& name, mode_t mode,
          const OutputSetFiles& files, const std::string& manifest)
      : parent_(parent) {
    for (int attempt = 0; attempt < 100 && name_.empty(); ++attempt) {
      const std::string candidate = temporary_name(name);
      if (::mkdirat(parent_fd, candidate.c_str(), 0700) == 0) name_ = candidate;
      else if (errno != EEXIST) throw_system_error(parent / name, "create a temporary folder beside it", errno);
    }
    if (name_.empty()) throw_system_error(parent / name, "create a temporary folder beside it", EEXIST);
    const fs::path path = parent / name_;
    const UniqueFd fd = open_folder(path, parent_fd, name_.c_str(), false);
    for (const auto& [file, contents] : files) write_new_file(fd.get(), path, file, contents);
    write_new_file(fd.get(), path, std::string(kManifestName), manifest);
    if (::fchmod(fd.get(), mode) != 0) throw_system_error(path, "set the folder's permissions", errno);
    if (::fsync(fd.get()) != 0) throw_system_error(path, "fsync", errno);
  }
  TempSet(const TempSet&) = delete;
  TempSet& operator=(const TempSet&) = delete;
  ~TempSet() {
    if (name_.empty()) return;
    std::error_code ignored;
    fs::remove_all(parent_ / name_, ignored);
  }
  const std::string& name() const { return name_; }

 private:
  fs::path parent_;
  std::string name_;
};

/// Each file replaced on its own, the manifest removed first and written
/// last: used where the folder holds files that are not insmc's.
void write_in_place(const fs::path& target, const OutputSetFiles& files, const std::string& manifest) {
  const UniqueFd fd = open_folder(target);
  const std::string manifest_name(kManifestName);
  remove_stale_temporaries(fd.get(), target, manifest_name);
  for (const auto& [file, contents] : files) remove_stale_temporaries(fd.get(), target, file);
  // Refuse before anything changes.
  std::vector<std::string> names{manifest_name};
  for (const auto& f : files) names.push_back(f.first);
  for (const std::string& n : names) {
    struct stat st {};
    if (::fstatat(fd.get(), n.c_str(), &st, AT_SYMLINK_NOFOLLOW) == 0 && !S_ISREG(st.st_mode))
      throw OutputError(target / n, "is " + describe_file_type(st.st_mode) +
                                        ", not a regular file; insmc replaces regular files only (remove it or "
                                        "choose another path)", EEXIST);
  }
  if (::unlinkat(fd.get(), manifest_name.c_str(), 0) != 0 && errno != ENOENT)
    throw_system_error(target / manifest_name, "remove", errno);
  for (const auto& [file, contents] : files) replace_file_at(fd.get(), target, file, contents);
  replace_file_at(fd.get(), target, manifest_name, manifest);
}

void check_file_names(const fs::path& target, const OutputSetFiles& files) {
  std::set<std::string> seen;
  for (const auto& f : files) {
    const std::string& n = f.first;
    if (n.empty() || n.front() == '.' || n.find('/') != std::string::npos || !seen.insert(n).second)
      throw OutputError(target / n, "is not a valid name for a file of an output set", EINVAL);
  }
}

}  // namespace

OutputFolder::OutputFolder(const std::string& path, std::string command, const std::vector<std::string>& expected_files)
    : command_(std::move(command)) {
  const OutputTarget t = check_folder_target(path);
  target_ = t.path;
  parent_ = t.path.parent_path();
  name_ = t.path.filename().string();
  if (t.exists) {
    const UniqueFd fd = open_folder(target_);
    for (const std::string& f : expected_files) {
      struct stat st {};
      if (::fstatat(fd.get(), f.c_str(), &st, AT_SYMLINK_NOFOLLOW) == 0 && !S_ISREG(st.st_mode))
        throw OutputError(target_ / f, "is " + describe_file_type(st.st_mode) +
                                           ", not a regular file; insmc replaces regular files only (remove it or "
                                           "choose another path)", EEXIST);
    }
  } else {
    std::error_code ec;
    fs::create_directories(parent_, ec);
    if (ec) throw OutputError(parent_, "cannot create this folder for the output: " + ec.message(), ec.value());
  }
  lock_.emplace(parent_, name_);
  const UniqueFd parent_fd = open_folder(parent_);
  remove_stale_temporaries(parent_fd.get(), parent_, name_);
}

SetPlacement OutputFolder::write(const OutputSetFiles& files) {
  check_file_names(target_, files);
  OutputManifest wanted{command_, {}};
  for (const auto& f : files) wanted.files.push_back(f.first);
  std::sort(wanted.files.begin(), wanted.files.end());
  const std::string manifest = render_manifest(wanted);

  const UniqueFd parent_fd = open_folder(parent_);
  struct stat st {};
  if (::fstatat(parent_fd.get(), name_.c_str(), &st, AT_SYMLINK_NOFOLLOW) != 0) {
    if (errno != ENOENT) throw_system_error(target_, "inspect", errno);
    TempSet temp(parent_fd.get(), parent_, name_, default_folder_mode(), files, manifest);
    if (::renameat2(parent_fd.get(), temp.name().c_str(), parent_fd.get(), name_.c_str(), RENAME_NOREPLACE) == 0) {
      if (::fsync(parent_fd.get()) != 0) throw_system_error(parent_, "fsync", errno);
      return SetPlacement::kNew;
    }
    // Created by someone else meanwhile (EEXIST), or a file system without
    // renameat2: decide again below on what is there now.
    if (errno != EEXIST && errno != EINVAL && errno != ENOSYS) throw_system_error(target_, "move the set in", errno);
    if (::fstatat(parent_fd.get(), name_.c_str(), &st, AT_SYMLINK_NOFOLLOW) != 0)
      throw_system_error(target_, "inspect", errno);
  }
  if (S_ISLNK(st.st_mode)) {
    struct stat followed {};
    if (::stat(target_.c_str(), &followed) != 0 || !S_ISDIR(followed.st_mode))
      throw OutputError(target_, "is a symbolic link that does not lead to a folder", ENOTDIR);
  } else if (!S_ISDIR(st.st_mode)) {
    throw OutputError(target_, "exists and is " + describe_file_type(st.st_mode) + ", not a folder", ENOTDIR);
  }

  // Swapped only where the lock file could be made beside it (the parent
  // is writable; otherwise the folder itself is locked and must stay), and
  // never the working directory (the shell would be left in a removed one).
  const bool swappable = S_ISDIR(st.st_mode) && !lock_->lock_file().empty() && !same_file(target_, ".") &&
                         holds_only_a_set_like(open_folder(target_, parent_fd.get(), name_.c_str(), false).get(),
                                               target_, wanted);
  if (swappable) {
    TempSet temp(parent_fd.get(), parent_, name_, st.st_mode & 07777, files, manifest);
    if (::renameat2(parent_fd.get(), temp.name().c_str(), parent_fd.get(), name_.c_str(), RENAME_EXCHANGE) == 0) {
      if (::fsync(parent_fd.get()) != 0) throw_system_error(parent_, "fsync", errno);
      // `temp` now holds the old set: its destructor removes it, unless a
      // file that is not the set's has appeared in it since the check; then
      // it is kept, visibly, as DIR.insmc-old-XXXXXX (never deleted).
      const UniqueFd old_fd = open_folder(parent_ / temp.name(), parent_fd.get(), temp.name().c_str(), false);
      if (!holds_only_a_set_like(old_fd.get(), parent_ / temp.name(), wanted)) {
        const std::string kept = name_ + ".insmc-old-" + temp.name().substr(temp.name().size() - 6);
        ::renameat(parent_fd.get(), temp.name().c_str(), parent_fd.get(), kept.c_str());
      }
      return SetPlacement::kExchanged;
    }
    // A mount point (EBUSY), another file system (EXDEV) or no renameat2
    // (EINVAL, ENOSYS): write in place instead.
    if (errno != EBUSY && errno != EXDEV && errno != EINVAL && errno != ENOSYS && errno != ENOTSUP)
      throw_system_error(target_, "swap the new set in", errno);
  }
  write_in_place(target_, files, manifest);
  return SetPlacement::kInPlace;
}

}  // namespace insmc::mc
