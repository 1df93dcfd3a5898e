#include "montecarlo/report/output_lock.h"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "montecarlo/report/output_error.h"

namespace insmc::mc {

namespace {

[[noreturn]] void held_by_another(const std::filesystem::path& target, const std::filesystem::path& lock) {
  throw OutputError(target,
                    "another insmc is writing this output now (it holds the lock " + lock.string() +
                        "); wait for it to finish or choose another path",
                    EWOULDBLOCK);
}

}  // namespace

OutputLock::OutputLock(const std::filesystem::path& given_dir, const std::string& given_name) {
  // Every alias of one output (a symbolic link to its folder, a path through
  // a linked parent) takes the one lock beside what it resolves to.
  std::error_code ec;
  const std::filesystem::path resolved = std::filesystem::weakly_canonical(given_dir / given_name, ec);
  const bool use_resolved = !ec && resolved.has_filename() && resolved.has_parent_path();
  const std::filesystem::path dir = use_resolved ? resolved.parent_path() : given_dir;
  const std::string name = use_resolved ? resolved.filename().string() : given_name;
  const std::filesystem::path target = dir / name;
  const std::filesystem::path lock = dir / ("." + name + ".insmc-lock");
  // A holder unlinks the lock file before it unlocks, so a lock taken on a
  // file that is no longer (or no longer the one) at that name is worthless:
  // retry on the file now there.
  for (int attempt = 0; attempt < 100; ++attempt) {
    UniqueFd fd(::open(lock.c_str(), O_RDWR | O_CREAT | O_NOFOLLOW | O_CLOEXEC, 0666));
    if (!fd.valid()) {
      const int error = errno;
      struct stat st {};
      if ((error == EACCES || error == EPERM || error == EROFS) && ::lstat(target.c_str(), &st) == 0 &&
          S_ISDIR(st.st_mode)) {
        fd = UniqueFd(::open(target.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC));
        if (!fd.valid()) throw_system_error(target, "open the folder to lock it", errno);
        if (::flock(fd.get(), LOCK_EX | LOCK_NB) != 0) {
          if (errno == EWOULDBLOCK) held_by_another(target, target);
          throw_system_error(target, "lock the folder", errno);
        }
        fd_ = std::move(fd);
        return;
      }
      // Nothing can be created beside the output (a read-only or special
      // file system, a parent that is not a folder): say so of the output
      // itself, not of the lock file the user never named.
      throw OutputError(target,
                        "cannot create the output in " + dir.string() + " (" + std::strerror(error) +
                            "): choose a folder you can write to",
                        error);
    }
    if (::flock(fd.get(), LOCK_EX | LOCK_NB) != 0) {
      if (errno == EWOULDBLOCK) held_by_another(target, lock);
      throw_system_error(lock, "lock", errno);
    }
    struct stat held {}, now {};
    if (::fstat(fd.get(), &held) != 0) throw_system_error(lock, "inspect the lock file", errno);
    if (::lstat(lock.c_str(), &now) == 0 && now.st_dev == held.st_dev && now.st_ino == held.st_ino) {
      lock_file_ = lock;
      fd_ = std::move(fd);
      return;
    }
  }
  held_by_another(target, lock);
}

OutputLock::~OutputLock() {
  if (!fd_.valid()) return;  // moved from
  if (!lock_file_.empty()) ::unlink(lock_file_.c_str());
  fd_.reset();
}

}  // namespace insmc::mc
