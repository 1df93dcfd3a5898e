#include "montecarlo/report/output_target.h"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <system_error>

#include "montecarlo/report/atomic_file.h"
#include "montecarlo/report/output_error.h"

namespace insmc::mc {

namespace {

namespace fs = std::filesystem;

struct Normalized {
  fs::path path;
  bool trailing_slash = false;
};

Normalized normalize(const std::string& text) {
  if (text.empty()) throw OutputError(text, "the path is empty", ENOENT);
  std::error_code ec;
  fs::path p = fs::absolute(text, ec);
  if (ec) throw OutputError(text, "cannot make the path absolute: " + ec.message(), ec.value());
  p = p.lexically_normal();
  Normalized n;
  while (p.has_relative_path() && p.filename().empty()) {  // "dir/" -> "dir"
    p = p.parent_path();
    n.trailing_slash = true;
  }
  n.trailing_slash = n.trailing_slash || text.back() == '/';
  if (!p.has_relative_path()) throw OutputError(text, "is the root folder", EISDIR);
  n.path = p;
  return n;
}

[[noreturn]] void not_writable(const fs::path& reported, const fs::path& folder, int error) {
  const std::string what = reported == folder ? "the folder" : "its folder " + folder.string();
  throw_system_error(reported, what + " is not writable", error);
}

void check_writable_folder(const fs::path& reported, const fs::path& folder) {
  struct stat st {};
  if (::stat(folder.c_str(), &st) != 0) {
    if (errno == ENOENT || errno == ENOTDIR)
      throw OutputError(reported, "its folder " + folder.string() + " does not exist", errno);
    throw_system_error(reported, "cannot inspect its folder " + folder.string(), errno);
  }
  if (!S_ISDIR(st.st_mode))
    throw OutputError(reported, "cannot be created: " + folder.string() + " is " + describe_file_type(st.st_mode) +
                                    ", not a folder", ENOTDIR);
  // access(2) also reports a read-only file system (EROFS), even to root.
  if (::access(folder.c_str(), W_OK | X_OK) != 0) not_writable(reported, folder, errno);
}

}  // namespace

OutputTarget check_folder_target(const std::string& text) {
  const fs::path p = normalize(text).path;
  struct stat st {};
  if (::lstat(p.c_str(), &st) == 0) {
    if (S_ISLNK(st.st_mode)) {
      struct stat followed {};
      if (::stat(p.c_str(), &followed) != 0 || !S_ISDIR(followed.st_mode))
        throw OutputError(p, "is a symbolic link that does not lead to a folder", ENOTDIR);
    } else if (!S_ISDIR(st.st_mode)) {
      throw OutputError(p, "exists and is " + describe_file_type(st.st_mode) + ", not a folder", ENOTDIR);
    }
    if (::access(p.c_str(), W_OK | X_OK) != 0) not_writable(p, p, errno);
    return {p, true};
  }
  if (errno != ENOENT && errno != ENOTDIR) throw_system_error(p, "cannot inspect", errno);
  // Missing: the nearest existing ancestor must be a writable folder.
  fs::path ancestor = p.parent_path();
  while (ancestor.has_relative_path() && ::lstat(ancestor.c_str(), &st) != 0 && (errno == ENOENT || errno == ENOTDIR))
    ancestor = ancestor.parent_path();
  check_writable_folder(p, ancestor);
  return {p, false};
}

OutputTarget check_file_target(const std::string& text) {
  const Normalized n = normalize(text);
  if (n.trailing_slash) throw OutputError(text, "ends in '/': it names a folder, give a file name", EISDIR);
  struct stat st {};
  bool exists = false;
  if (::lstat(n.path.c_str(), &st) == 0) {
    if (!S_ISREG(st.st_mode))
      throw OutputError(n.path, "exists and is " + describe_file_type(st.st_mode) +
                                    ", not a regular file; insmc replaces regular files only", EEXIST);
    exists = true;
  } else if (errno != ENOENT) {
    if (errno == ENOTDIR) check_writable_folder(n.path, n.path.parent_path());
    throw_system_error(n.path, "cannot inspect", errno);
  }
  check_writable_folder(n.path, n.path.parent_path());
  return {n.path, exists};
}

}  // namespace insmc::mc
