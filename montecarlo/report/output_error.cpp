#include "montecarlo/report/output_error.h"

#include <cerrno>
#include <cstring>

namespace insmc::mc {

OutputError::OutputError(std::filesystem::path path, std::string problem, int error)
    : std::runtime_error(path.string() + ": " + problem),
      path_(std::move(path)),
      problem_(std::move(problem)),
      error_(error) {}

bool OutputError::user_fixable() const { return error_ != EBADF && error_ != EFAULT && error_ != EINVAL; }

void throw_system_error(const std::filesystem::path& path, const std::string& step, int error) {
  throw OutputError(path, step + ": " + std::strerror(error), error);
}

}  // namespace insmc::mc
