#include "montecarlo/write/plot/gnuplot.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <fmt/format.h>

extern char** environ;

namespace insmc::mc {
namespace {

namespace fs = std::filesystem;

/// The temporary folder, removed when it goes out of scope.
class ScratchFolder {
 public:
  ScratchFolder() {
    std::string pattern = (fs::temp_directory_path() / "insmc-plot-XXXXXX").string();
    if (!::mkdtemp(pattern.data()))
      throw std::runtime_error(fmt::format("cannot make a temporary folder for gnuplot: {}", std::strerror(errno)));
    path_ = pattern;
  }
  ~ScratchFolder() {
    std::error_code ignored;
    fs::remove_all(path_, ignored);
  }
  ScratchFolder(const ScratchFolder&) = delete;
  ScratchFolder& operator=(const ScratchFolder&) = delete;
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

std::string read_all(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

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
  ScratchFolder folder;
  const fs::path script_path = folder.path() / "plot.gp", messages_path = folder.path() / "messages.txt";
  {
    std::ofstream out(script_path, std::ios::binary);
    out << script;
    if (!out) throw std::runtime_error("cannot write the gnuplot script to a temporary folder");
  }
  // gnuplot runs in the folder (its `cd`), reads the script, and sends its
  // messages to a file; stdin is /dev/null so it never waits for input.
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, messages_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
  posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
  const std::string cd = "cd " + gnuplot_quote(folder.path().string());
  std::string program = kGnuplotProgram, dash_e = "-e", file = script_path.string();
  char* argv[] = {program.data(), dash_e.data(), const_cast<char*>(cd.c_str()), file.data(), nullptr};
  pid_t pid = 0;
  const int spawned = posix_spawnp(&pid, kGnuplotProgram, &actions, nullptr, argv, environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawned != 0) throw std::runtime_error(gnuplot_missing_message());
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) throw std::runtime_error(fmt::format("waiting for gnuplot: {}", std::strerror(errno)));
  }
  const std::string messages = read_all(messages_path);
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw std::runtime_error(fmt::format("gnuplot failed ({}): {}",
                                         WIFEXITED(status) ? fmt::format("exit {}", WEXITSTATUS(status))
                                                           : fmt::format("signal {}", WTERMSIG(status)),
                                         first_error_line(messages)));
  std::vector<std::string> bytes;
  for (const std::string& name : outputs) {
    const fs::path p = folder.path() / name;
    std::error_code ec;
    if (!fs::is_regular_file(p, ec) || fs::file_size(p, ec) == 0)
      throw std::runtime_error(fmt::format("gnuplot wrote no {} ({})", name, first_error_line(messages)));
    bytes.push_back(read_all(p));
  }
  return bytes;
}

std::string figure_script(const FigureScript& f) {
  std::string out = fmt::format(
      "# {}\n# Written by insmc with its data inline; render again with: gnuplot {}.gp\n"
      "# (writes {}.svg and {}.png in the current folder).\n",
      f.title, f.stem, f.stem, f.stem);
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
  std::string out = "\"";
  for (const char c : text) {
    if (c == '\\' || c == '"') out += '\\';
    if (c == '\n') {
      out += "\\n";
      continue;
    }
    out += c;
  }
  return out + "\"";
}

}  // namespace insmc::mc
