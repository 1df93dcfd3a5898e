#include "apps/output_paths.h"

#include <sys/stat.h>

#include <filesystem>
#include <fmt/format.h>
#include <system_error>
#include <utility>

#include "lib/common/assert.h"
#include "lib/common/input_error.h"
#include "lib/common/input_text.h"
#include "montecarlo/report/output_error.h"
#include "montecarlo/report/plot/gnuplot.h"

namespace insmc::app {

namespace {

/// The path as the user gave it, made absolute like the writers do, to
/// leave it out of a message that already names it.
std::filesystem::path as_checked(const std::string& text) {
  std::error_code ec;
  std::filesystem::path p = std::filesystem::absolute(text, ec).lexically_normal();
  while (p.has_relative_path() && p.filename().empty()) p = p.parent_path();
  return p;
}

/// Runs `f`; an OutputError the user can fix becomes InputError (exit 2)
/// "OPTION = PATH: problem"; a defect stays an error (exit 3).
template <class F>
void as_input_errors(const std::string& option, const std::string& text, F&& f) {
  try {
    f();
  } catch (const mc::OutputError& e) {
    if (!e.user_fixable()) throw;
    const bool same = e.path() == as_checked(text) || e.path() == text;
    throw InputError(option, text, same ? e.problem() : e.what());
  }
}

/// InputError when `candidate` (an output about to be written) is the same
/// file as one of `inputs` (compared by device and inode, so links and
/// other spellings of a path are caught); `except`: an input option that
/// may be the output.
void refuse_inputs(const std::string& option, const std::string& text, const std::filesystem::path& candidate,
                   const std::vector<InputFile>& inputs, std::string_view except = {}) {
  struct stat out {};
  if (::stat(candidate.c_str(), &out) != 0) return;  // nothing there yet: it cannot be an input
  for (const InputFile& in : inputs) {
    struct stat st {};
    if (in.option == except || ::stat(in.path.c_str(), &st) != 0) continue;
    if (st.st_dev == out.st_dev && st.st_ino == out.st_ino)
      throw InputError(option, text,
                       fmt::format("{} is the file of {} {}: an output may not replace an input; choose another path",
                                   candidate == as_checked(text) ? "it" : candidate.string(), in.option,
                                   echo_input(in.path, 256)));
  }
}

}  // namespace

std::vector<InputFile> input_files(const po::variables_map& vm) {
  std::vector<InputFile> out;
  for (const char* name : {"records", "input", "bounds", "config", "from", "resume"}) {
    if (!vm.count(name)) continue;
    const boost::any& v = vm[name].value();
    if (const auto* one = boost::any_cast<std::string>(&v)) out.push_back({std::string("--") + name, *one});
    if (const auto* many = boost::any_cast<std::vector<std::string>>(&v))
      for (const std::string& path : *many) out.push_back({std::string("--") + name, path});
  }
  return out;
}

OutputFolderOption::OutputFolderOption(std::string option, std::string path, const std::string& command,
                                       const std::vector<std::string>& expected_files,
                                       const std::vector<InputFile>& inputs)
    : option_(std::move(option)), text_(std::move(path)), expected_(expected_files) {
  refuse_inputs(option_, text_, as_checked(text_), inputs);
  for (const std::string& name : expected_files) refuse_inputs(option_, text_, as_checked(text_) / name, inputs);
  as_input_errors(option_, text_, [&] { folder_.emplace(text_, command, expected_files); });
}

void OutputFolderOption::write(const mc::OutputSetFiles& files) {
  for (const auto& f : files)  // what was checked before the work is what is written
    INSMC_ASSERT(expected_.empty() || std::find(expected_.begin(), expected_.end(), f.first) != expected_.end(),
                 "{} writes {}, which it did not name before the work", option_, f.first);
  as_input_errors(option_, text_, [&] { folder_->write(files); });
}

OutputFileOption::OutputFileOption(std::string option, std::string path, const std::vector<InputFile>& inputs)
    : option_(std::move(option)), text_(std::move(path)) {
  refuse_inputs(option_, text_, as_checked(text_), inputs, option_ == "--checkpoint" ? "--resume" : "");
  as_input_errors(option_, text_, [&] { file_.emplace(text_); });
}

void OutputFileOption::write(std::string_view contents) const {
  as_input_errors(option_, text_, [&] { file_->write(contents); });
}

std::optional<OutputFolderOption> prepare_report_folder(const po::variables_map& vm, const mc::ReportOutline& outline,
                                                        const std::vector<InputFile>& read_before) {
  std::optional<OutputFolderOption> out;
  if (!vm.count("out")) return out;
  std::vector<InputFile> inputs = input_files(vm);
  inputs.insert(inputs.end(), read_before.begin(), read_before.end());
  out.emplace("--out", vm["out"].as<std::string>(), outline.command, outline.set_names(), inputs);
  if (!outline.figure_stems.empty() && !mc::gnuplot_available())
    throw InputError("--out", vm["out"].as<std::string>(), mc::gnuplot_missing_message());
  return out;
}

std::string out_folder_help(const mc::ReportOutline& outline) {
  return fmt::format("folder for {}, created if needed", outline.set_text());
}

}  // namespace insmc::app
