#pragma once
// Runs the built insmc (INSMC_BINARY_PATH, compiled in by CMake) with a shell
// command line and captures its exit code, stdout and stderr.
#include <filesystem>
#include <string>

namespace insmc::testing {

struct ProgramResult {
  int exit_code;
  std::string out, err;
};

/// `args` is appended to the program path; it is passed through /bin/sh.
ProgramResult run_insmc(const std::string& args);

/// A fresh empty folder under the system temp dir, removed by the destructor.
class TempDir {
 public:
  TempDir();
  ~TempDir();
  const std::filesystem::path& path() const { return path_; }
  std::string str() const { return path_.string(); }

 private:
  std::filesystem::path path_;
};

std::string read_file(const std::filesystem::path& p);

}  // namespace insmc::testing
