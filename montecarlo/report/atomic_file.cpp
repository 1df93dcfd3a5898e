#include "montecarlo/report/atomic_file.h"

#include <dirent.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <random>
#include <system_error>
#include <vector>

#include "montecarlo/report/output_error.h"
#include "montecarlo/report/unique_fd.h"

namespace insmc::mc {

namespace {

constexpr std::string_view kTempInfix = ".insmc-tmp-";
constexpr std::size_t kRandomLetters = 6;
constexpr std::string_view kLetters = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789";

bool is_letter(char c) { return kLetters.find(c) != std::string_view::npos; }

// Unlinks the temporary unless released: every failure path leaves nothing.
class TempNameGuard {
 public:
  TempNameGuard(int dir_fd, std::string name) : dir_fd_(dir_fd), name_(std::move(name)) {}
  TempNameGuard(const TempNameGuard&) = delete;
  TempNameGuard& operator=(const TempNameGuard&) = delete;
  ~TempNameGuard() {
    if (armed_) ::unlinkat(dir_fd_, name_.c_str(), 0);
  }
  void release() { armed_ = false; }

 private:
  int dir_fd_;
  std::string name_;
  bool armed_ = true;
};

void write_all(int fd, const std::filesystem::path& path, std::string_view contents) {
  const char* data = contents.data();
  std::size_t left = contents.size();
  while (left > 0) {
    const ssize_t written = ::write(fd, data, left);
    if (written < 0) {
      if (errno == EINTR) continue;
      throw_system_error(path, "write", errno);
    }
    data += written;
    left -= static_cast<std::size_t>(written);
  }
}

// Writes, fsyncs and closes a descriptor just created for `path`.
void fill_and_close(UniqueFd fd, const std::filesystem::path& path, std::string_view contents) {
  write_all(fd.get(), path, contents);
  if (::fsync(fd.get()) != 0) throw_system_error(path, "fsync", errno);
  if (const int error = fd.close_checked(); error != 0) throw_system_error(path, "close", error);
}

UniqueFd create_exclusive(int dir_fd, const std::string& name) {
  return UniqueFd(::openat(dir_fd, name.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666));
}

}  // namespace

std::string describe_file_type(mode_t mode) {
  if (S_ISDIR(mode)) return "a folder";
  if (S_ISFIFO(mode)) return "a FIFO";
  if (S_ISCHR(mode) || S_ISBLK(mode)) return "a device";
  if (S_ISLNK(mode)) return "a symbolic link";
  if (S_ISSOCK(mode)) return "a socket";
  return "a file";
}

std::string temporary_name(std::string_view name) {
  thread_local std::mt19937_64 random{std::random_device{}() ^ (static_cast<std::uint64_t>(::getpid()) << 32)};
  std::string out = "." + std::string(name) + std::string(kTempInfix);
  for (std::size_t i = 0; i < kRandomLetters; ++i) out += kLetters[random() % kLetters.size()];
  return out;
}

bool is_temporary_of(std::string_view entry, std::string_view name) {
  const std::size_t prefix = 1 + name.size() + kTempInfix.size();
  if (entry.size() != prefix + kRandomLetters || entry[0] != '.' || entry.substr(1, name.size()) != name ||
      entry.substr(1 + name.size(), kTempInfix.size()) != kTempInfix)
    return false;
  for (const char c : entry.substr(prefix))
    if (!is_letter(c)) return false;
  return true;
}

void remove_stale_temporaries(int dir_fd, const std::filesystem::path& dir, std::string_view name) {
  const int listing_fd = ::openat(dir_fd, ".", O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (listing_fd < 0) throw_system_error(dir, "open the folder", errno);
  DIR* listing = ::fdopendir(listing_fd);
  if (listing == nullptr) {
    const int error = errno;
    ::close(listing_fd);
    throw_system_error(dir, "list the folder", error);
  }
  std::vector<std::string> stale;
  while (const dirent* e = ::readdir(listing))
    if (is_temporary_of(e->d_name, name)) stale.emplace_back(e->d_name);
  ::closedir(listing);
  for (const std::string& entry : stale) {
    struct stat st {};
    if (::fstatat(dir_fd, entry.c_str(), &st, AT_SYMLINK_NOFOLLOW) != 0) continue;
    if (S_ISDIR(st.st_mode)) {
      // A set's temporary folder: insmc's files only (mkdtemp made it 0700).
      // remove_all never follows a symbolic link inside it.
      std::error_code ec;
      std::filesystem::remove_all(dir / entry, ec);
      if (ec) throw OutputError(dir / entry, "cannot remove this stale temporary folder: " + ec.message(), ec.value());
    } else if (::unlinkat(dir_fd, entry.c_str(), 0) != 0 && errno != ENOENT) {
      throw_system_error(dir / entry, "remove this stale temporary file", errno);
    }
  }
}

void write_new_file(int dir_fd, const std::filesystem::path& dir, const std::string& name,
                    std::string_view contents) {
  UniqueFd fd = create_exclusive(dir_fd, name);
  if (!fd.valid()) throw_system_error(dir / name, "create", errno);
  TempNameGuard guard(dir_fd, name);
  fill_and_close(std::move(fd), dir / name, contents);
  guard.release();
}

void replace_file_at(int dir_fd, const std::filesystem::path& dir, const std::string& name,
                     std::string_view contents) {
  const std::filesystem::path path = dir / name;
  struct stat st {};
  if (::fstatat(dir_fd, name.c_str(), &st, AT_SYMLINK_NOFOLLOW) == 0) {
    if (!S_ISREG(st.st_mode))
      throw OutputError(path, "is " + describe_file_type(st.st_mode) + ", not a regular file; insmc replaces "
                              "regular files only (remove it or choose another path)", EEXIST);
  } else if (errno != ENOENT) {
    throw_system_error(path, "inspect", errno);
  }
  std::string temp;
  UniqueFd fd;
  for (int attempt = 0; attempt < 100 && !fd.valid(); ++attempt) {
    temp = temporary_name(name);
    fd = create_exclusive(dir_fd, temp);
    if (!fd.valid() && errno != EEXIST) throw_system_error(path, "create a temporary file beside it", errno);
  }
  if (!fd.valid()) throw_system_error(path, "create a temporary file beside it", EEXIST);
  TempNameGuard guard(dir_fd, temp);
  fill_and_close(std::move(fd), path, contents);
  if (::renameat(dir_fd, temp.c_str(), dir_fd, name.c_str()) != 0) throw_system_error(path, "rename", errno);
  guard.release();
  if (::fsync(dir_fd) != 0) throw_system_error(dir, "fsync the folder", errno);
}

void write_file_atomically(const std::filesystem::path& path, std::string_view contents) {
  const std::filesystem::path name = path.filename();
  if (name.empty() || name == "." || name == "..")
    throw OutputError(path, "names a folder, not a file", EISDIR);
  std::filesystem::path dir = path.parent_path();
  if (dir.empty()) dir = ".";
  const UniqueFd dir_fd(::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC));
  if (!dir_fd.valid()) throw_system_error(path, "open its folder", errno);
  replace_file_at(dir_fd.get(), dir, name.string(), contents);
}

}  // namespace insmc::mc
