#pragma once
// Runs the built insmc (INSMC_BINARY_PATH, compiled in by CMake) with a shell
// command line and captures its exit code, stdout and stderr; or starts it in
// the background, for tests that signal it.
#include <filesystem>
#include <string>

namespace insmc::testing {

struct ProgramResult {
  int exit_code;
  std::string out, err;
  long peak_rss_kb = 0;  ///< run_limited only: the largest resident size of the program
};

/// `args` is appended to the program path; it is passed through /bin/sh.
ProgramResult run_insmc(const std::string& args);

/// The path of the built insmc.
std::string insmc_path();

/// Whether `text` (a program's output) contains `what`.
inline bool has(const std::string& text, const std::string& what) { return text.find(what) != std::string::npos; }

/// A whole /bin/sh command line (e.g. insmc under mpirun), run to the end.
ProgramResult run_shell(const std::string& command);

/// Whether run_limited's address-space limit applies: not under
/// AddressSanitizer, which reserves terabytes of address space (the
/// sanitizer build checks the rest).
bool address_space_limit_applies();

/// insmc with `args` (through /bin/sh), killed after `seconds`; the exit
/// code is 128 + the signal when a signal ended it, and peak_rss_kb the
/// largest resident size it reached (getrusage of the waited child). With
/// `limit_4gb`, under a 4 GB address-space limit where it applies, so that a
/// runaway allocation fails fast instead of taking the machine.
ProgramResult run_limited(const std::string& args, int seconds, bool limit_4gb = false);

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

/// A /bin/sh command line started in the background (`exec`ed, so a signal
/// reaches the program itself), for tests that interrupt it.
class BackgroundProgram {
 public:
  explicit BackgroundProgram(const std::string& command);
  /// Kills (SIGKILL) and reaps the program if it is still running.
  ~BackgroundProgram();
  BackgroundProgram(const BackgroundProgram&) = delete;
  BackgroundProgram& operator=(const BackgroundProgram&) = delete;
  void send(int signal);
  /// Waits for the end: exit code (128 + signal when killed), stdout, stderr.
  ProgramResult wait();

 private:
  TempDir io_;
  int pid_ = -1;
};

std::string read_file(const std::filesystem::path& p);

}  // namespace insmc::testing
