#include "apps/output_paths.h"

#include <filesystem>
#include <system_error>
#include <utility>

#include "lib/common/input_error.h"
#include "montecarlo/write/output_error.h"
#include "montecarlo/write/plot/gnuplot.h"

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

}  // namespace

OutputFolderOption::OutputFolderOption(std::string option, std::string path, const std::string& command,
                                       const std::vector<std::string>& expected_files)
    : option_(std::move(option)), text_(std::move(path)) {
  as_input_errors(option_, text_, [&] { folder_.emplace(text_, command, expected_files); });
}

void OutputFolderOption::write(const OutputFiles& files) {
  as_input_errors(option_, text_, [&] { folder_->write(mc::OutputSetFiles(files.begin(), files.end())); });
}

std::optional<OutputFolderOption> prepare_output_folder(const po::variables_map& vm, const std::string& command,
                                                        const std::vector<std::string>& expected_files) {
  std::optional<OutputFolderOption> out;
  if (vm.count("out")) out.emplace("--out", vm["out"].as<std::string>(), command, expected_files);
  return out;
}

OutputFileOption::OutputFileOption(std::string option, std::string path)
    : option_(std::move(option)), text_(std::move(path)) {
  as_input_errors(option_, text_, [&] { file_.emplace(text_); });
}

void OutputFileOption::write(std::string_view contents) const {
  as_input_errors(option_, text_, [&] { file_->write(contents); });
}

std::optional<OutputFolderOption> prepare_figure_folder(const po::variables_map& vm, const std::string& command,
                                                        std::vector<std::string> other_files,
                                                        const std::string& figure_stem) {
  for (std::string& name : mc::figure_file_names(figure_stem)) other_files.push_back(std::move(name));
  std::optional<OutputFolderOption> out = prepare_output_folder(vm, command, other_files);
  if (out && !mc::gnuplot_available()) throw InputError("--out", vm["out"].as<std::string>(), mc::gnuplot_missing_message());
  return out;
}

}  // namespace insmc::app
