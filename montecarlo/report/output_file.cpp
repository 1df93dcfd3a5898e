#include "montecarlo/report/output_file.h"

#include <fcntl.h>

#include <cerrno>

#include "montecarlo/report/atomic_file.h"
#include "montecarlo/report/output_error.h"
#include "montecarlo/report/output_target.h"
#include "montecarlo/report/unique_fd.h"

namespace insmc::mc {

namespace {

UniqueFd open_parent(const std::filesystem::path& path) {
  UniqueFd fd(::open(path.parent_path().c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC));
  if (!fd.valid()) throw_system_error(path, "open its folder", errno);
  return fd;
}

}  // namespace

OutputFile::OutputFile(const std::string& path) : path_(check_file_target(path).path) {
  lock_.emplace(path_.parent_path(), path_.filename().string());
  remove_stale_temporaries(open_parent(path_).get(), path_.parent_path(), path_.filename().string());
}

void OutputFile::write(std::string_view contents) const {
  replace_file_at(open_parent(path_).get(), path_.parent_path(), path_.filename().string(), contents);
}

}  // namespace insmc::mc
