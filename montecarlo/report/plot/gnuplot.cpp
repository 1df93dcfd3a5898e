#include "montecarlo/report/plot/gnuplot.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/mman.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string_view>

#include <fmt/format.h>

#include "lib/common/assert.h"
#include "lib/common/input_error.h"

extern char** environ;

namespace insmc::mc {
namespace {

namespace fs = std::filesystem;

/// An anonymous in-memory file (memfd): gnuplot's script, its outputs and
/// its messages live in these, never in a folder, so nothing is left
/// behind when insmc or gnuplot is killed.
class MemoryFile {
 public:
  explicit MemoryFile(const char* name) {
    const int fd = ::memfd_create(name, MFD_CLOEXEC);
    // Above the descriptors gnuplot gets (0-2 and 3 + its outputs): a run
    // started with 0, 1 or 2 closed would otherwise hand one out here, and
    // the dup2 of another file onto it would take it away.
    fd_ = fd < 0 ? -1 : ::fcntl(fd, F_DUPFD_CLOEXEC, kLowestFd);
    if (fd >= 0) ::close(fd);
    if (fd_ < 0)
      throw InputError("gnuplot", "(in-memory files)",
                       fmt::format("cannot make one for the plots: {}", std::strerror(errno)));
  }
  ~MemoryFile() { ::close(fd_); }
  MemoryFile(const MemoryFile&) = delete;
  MemoryFile& operator=(const MemoryFile&) = delete;
  int fd() const { return fd_; }
  static constexpr int kLowestFd = 16;

  void write_all(std::string_view bytes) const {
    while (!bytes.empty()) {
      const ssize_t n = ::write(fd_, bytes.data(), bytes.size());
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) throw std::runtime_error(fmt::format("cannot write gnuplot's script: {}", std::strerror(errno)));
      bytes.remove_prefix(static_cast<std::size_t>(n));
    }
    ::lseek(fd_, 0, SEEK_SET);
  }
  /// What the file holds (gnuplot reopened it by /dev/fd/N, so read from 0).
  std::string read_all() const {
    std::string out;
    char buffer[1 << 16];
    for (off_t at = 0;;) {
      const ssize_t n = ::pread(fd_, buffer, sizeof buffer, at);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) break;
      out.append(buffer, static_cast<std::size_t>(n));
      at += n;
    }
    return out;
  }

 private:
  int fd_;
};

/// The first line of gnuplot's messages that says what went wrong.
std::string first_error_line(const std::string& messages) {
  std::istringstream in(messages);
  std::string line, first;
  while (std::getline(in, line)) {
    if (line.find_first_not_of(" \t^") == std::string::npos) continue;
    if (first.empty()) first = line;
    if (line.find("rror") != std::string::npos) return line;
  }
  return first.empty() ? "no message" : first;
}

}  // namespace

bool gnuplot_available() {
  const char* path = std::getenv("PATH");
  std::string dirs = path ? path : "/usr/bin:/bin";
  std::size_t p = 0;
  while (p <= dirs.size()) {
    const std::size_t q = std::min(dirs.find(':', p), dirs.size());
    const fs::path candidate = fs::path(dirs.substr(p, q - p).empty() ? "." : dirs.substr(p, q - p)) / kGnuplotProgram;
    if (::access(candidate.c_str(), X_OK) == 0) return true;
    p = q + 1;
  }
  return false;
}

std::string gnuplot_missing_message() {
  return "gnuplot is not on PATH: the plots need it (Debian package gnuplot-nox; scripts/install-deps.sh installs it)";
}

std::vector<std::string> render_gnuplot(const std::string& script, const std::vector<std::string>& outputs) {
  // gnuplot reads the script on stdin and writes output i to /dev/fd/(3 + i),
  // an in-memory file of ours: the script's `set output "NAME"` lines are
  // pointed there for this run only (the .gp kept for the user keeps NAME).
  constexpr int kFirstOutputFd = 3;
  INSMC_ASSERT(kFirstOutputFd + static_cast<int>(outputs.size()) <= MemoryFile::kLowestFd, "{} outputs", outputs.size());
  std::string run = script;
  std::vector<std::unique_ptr<MemoryFile>> files;
  for (std::size_t i = 0; i < outputs.size(); ++i) {
    files.push_back(std::make_unique<MemoryFile>("insmc-plot-output"));
    const std::string named = "set output " + gnuplot_quote(outputs[i]);
    const std::string fd_path = "set output " + gnuplot_quote(fmt::format("/dev/fd/{}", kFirstOutputFd + static_cast<int>(i)));
    for (std::size_t at = run.find(named); at != std::string::npos; at = run.find(named, at + fd_path.size()))
      run.replace(at, named.size(), fd_path);
  }
  const MemoryFile input("insmc-plot-script"), messages("insmc-plot-messages");
  input.write_all(run);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, input.fd(), STDIN_FILENO);
  posix_spawn_file_actions_adddup2(&actions, messages.fd(), STDOUT_FILENO);
  posix_spawn_file_actions_adddup2(&actions, messages.fd(), STDERR_FILENO);
  for (std::size_t i = 0; i < files.size(); ++i)
    posix_spawn_file_actions_adddup2(&actions, files[i]->fd(), kFirstOutputFd + static_cast<int>(i));
  std::string program = kGnuplotProgram;
  char* argv[] = {program.data(), nullptr};
  pid_t pid = 0;
  const int spawned = posix_spawnp(&pid, kGnuplotProgram, &actions, nullptr, argv, environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawned != 0) throw std::runtime_error(gnuplot_missing_message());
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) throw std::runtime_error(fmt::format("waiting for gnuplot: {}", std::strerror(errno)));
  }
  const std::string said = messages.read_all();
  // gnuplot is another program: when it fails or is killed, nothing of the
  // output set is written and the user is told why (exit 2, not a defect).
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw InputError("gnuplot",
                     WIFEXITED(status) ? fmt::format("exit {}", WEXITSTATUS(status))
                                       : fmt::format("killed by signal {}", WTERMSIG(status)),
                     fmt::format("the plots could not be drawn, so no output was written ({})", first_error_line(said)));
  std::vector<std::string> bytes;
  for (std::size_t i = 0; i < outputs.size(); ++i) {
    bytes.push_back(files[i]->read_all());
    if (bytes.back().empty())
      throw InputError("gnuplot", "exit 0", fmt::format("it drew no {}, so no output was written ({})", outputs[i],
                                                        first_error_line(said)));
  }
  return bytes;
}

std::string figure_script(const FigureScript& f) {
  std::string out = fmt::format(
      "# {}\n# Written by insmc with its data inline; render again with: gnuplot {}.gp\n"
      "# (writes {}.svg and {}.png in the current folder).\n",
      gnuplot_comment(f.title), f.stem, f.stem, f.stem);
  out += f.data_and_settings;
  out += "set border linecolor \"#333333\"\n";
  out += fmt::format("set terminal svg size {},{} noenhanced font \"sans,11\" background \"white\"\nset output {}\n",
                     f.width, f.height, gnuplot_quote(f.stem + ".svg"));
  out += f.body;
  out += fmt::format("set terminal pngcairo size {},{} noenhanced font \"sans,10\" background \"white\"\nset output {}\n",
                     f.width, f.height, gnuplot_quote(f.stem + ".png"));
  return out + f.body + "unset output\n";
}

RenderedFigure render_figure(const std::string& stem, std::string script) {
  RenderedFigure r;
  std::vector<std::string> bytes = render_gnuplot(script, {stem + ".svg", stem + ".png"});
  r.script = std::move(script);
  r.svg = std::move(bytes[0]);
  r.png = std::move(bytes[1]);
  return r;
}

std::vector<std::string> figure_file_names(const std::string& stem) {
  return {stem + ".gp", stem + ".svg", stem + ".png"};
}

std::vector<std::pair<std::string, std::string>> figure_files(const std::string& stem, RenderedFigure figure) {
  return {{stem + ".gp", std::move(figure.script)},
          {stem + ".svg", std::move(figure.svg)},
          {stem + ".png", std::move(figure.png)}};
}

std::string empty_panel_plot(const std::string& note) {
  // Label 99 is the note's own; the ranges in the plot command hold for
  // this panel only.
  return fmt::format("set label 99 {} at graph 0.5, graph 0.5 center textcolor \"#555555\"\n"
                     "plot [0:1][1:10] NaN notitle\nunset label 99\n",
                     gnuplot_quote(note));
}

std::string gnuplot_quote(const std::string& text) {
  // gnuplot runs a `command` in backquotes even inside double quotes: a
  // file name like x`rm -rf ~`.csv in a title must stay text (\` is a
  // literal backquote). Other control bytes end the command line: dropped.
  std::string out = "\"";
  for (const char c : text) {
    if (c == '\n') {
      out += "\\n";
      continue;
    }
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) continue;
    if (c == '\\' || c == '"' || c == '`') out += '\\';
    out += c;
  }
  return out + "\"";
}

std::string gnuplot_comment(const std::string& text) {
  std::string out;
  for (const char c : text) out += static_cast<unsigned char>(c) < 0x20 || c == 0x7f ? ' ' : c;
  return out;
}

}  // namespace insmc::mc
