#include "tests/cli/run_program.h"

#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <fstream>
#include <random>
#include <spawn.h>
#include <sstream>
#include <stdexcept>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;  // POSIX: the environment, passed on to spawned programs

namespace insmc::testing {

std::string read_file(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

TempDir::TempDir() {
  std::random_device rd;
  path_ = std::filesystem::temp_directory_path() / ("insmc-cli-" + std::to_string(rd()) + std::to_string(rd()));
  std::filesystem::create_directories(path_);
}

TempDir::~TempDir() {
  std::error_code ec;
  std::filesystem::remove_all(path_, ec);
}

std::string insmc_path() { return INSMC_BINARY_PATH; }  // set by tests/CMakeLists.txt (NEEDS_PROGRAM)

ProgramResult run_shell(const std::string& command) {
  TempDir io;
  const auto out = io.path() / "out", err = io.path() / "err";
  const std::string cmd = command + " >" + out.string() + " 2>" + err.string() + " </dev/null";
  const int status = std::system(cmd.c_str());
  ProgramResult r{WIFEXITED(status) ? WEXITSTATUS(status) : -1, read_file(out), read_file(err)};
  return r;
}

ProgramResult run_insmc(const std::string& args) {
  std::string command = insmc_path();  // (not a temporary + literal: GCC 12's -Warray-bounds false positive)
  command += ' ';
  command += args;
  return run_shell(command);
}

bool address_space_limit_applies() {
#if defined(__SANITIZE_ADDRESS__)  // g++
  return false;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)  // clang
  return false;
#else
  return true;
#endif
#else
  return true;
#endif
}

ProgramResult run_limited(const std::string& args, int seconds, bool limit_4gb) {
  TempDir io;
  const std::string limit = limit_4gb && address_space_limit_applies() ? "ulimit -v 4194304; " : "";
  const std::string cmd = limit + "exec timeout -s KILL " + std::to_string(seconds) + " " + insmc_path() + " " + args +
                          " >" + (io.path() / "out").string() + " 2>" + (io.path() / "err").string() + " </dev/null";
  const char* argv[] = {"/bin/sh", "-c", cmd.c_str(), nullptr};
  pid_t pid = -1;
  if (posix_spawn(&pid, "/bin/sh", nullptr, nullptr, const_cast<char* const*>(argv), environ) != 0)
    throw std::runtime_error("posix_spawn failed: " + cmd);
  int status = 0;
  struct rusage usage {};
  while (wait4(pid, &status, 0, &usage) < 0)
    if (errno != EINTR) throw std::runtime_error("wait4 failed");
  // timeout exits 128 + 9 when it killed insmc, and passes a signal on as 128 + signal.
  const int code = WIFEXITED(status) ? WEXITSTATUS(status) : WIFSIGNALED(status) ? 128 + WTERMSIG(status) : -1;
  ProgramResult r{code, read_file(io.path() / "out"), read_file(io.path() / "err")};
  r.peak_rss_kb = usage.ru_maxrss;
  return r;
}

BackgroundProgram::BackgroundProgram(const std::string& command) {
  const std::string cmd = "exec " + command + " >" + (io_.path() / "out").string() + " 2>" +
                          (io_.path() / "err").string() + " </dev/null";
  const char* argv[] = {"/bin/sh", "-c", cmd.c_str(), nullptr};
  pid_t pid = -1;
  if (posix_spawn(&pid, "/bin/sh", nullptr, nullptr, const_cast<char* const*>(argv), environ) != 0)
    throw std::runtime_error("posix_spawn failed: " + command);
  pid_ = pid;
}

BackgroundProgram::~BackgroundProgram() {
  if (pid_ <= 0) return;
  kill(pid_, SIGKILL);
  waitpid(pid_, nullptr, 0);
}

void BackgroundProgram::send(int signal) {
  if (pid_ > 0) kill(pid_, signal);
}

ProgramResult BackgroundProgram::wait() {
  int status = 0;
  if (pid_ <= 0 || waitpid(pid_, &status, 0) != pid_) throw std::runtime_error("waitpid failed");
  pid_ = -1;
  const int code = WIFEXITED(status) ? WEXITSTATUS(status) : WIFSIGNALED(status) ? 128 + WTERMSIG(status) : -1;
  return {code, read_file(io_.path() / "out"), read_file(io_.path() / "err")};
}

}  // namespace insmc::testing
