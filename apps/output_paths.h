#pragma once
/// The output paths of the subcommands (--out DIR, --out FILE,
/// --checkpoint FILE): checked and locked before any work, so that a path
/// the user can fix is refused at once with exit code 2 (InputError naming
/// the option and the path), and written at the end as a whole
/// (montecarlo/report/output_set.h, output_file.h; docs/outputs.md).
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "apps/cli_common.h"
#include "montecarlo/report/output_file.h"
#include "montecarlo/report/output_set.h"
#include "montecarlo/report/report.h"

namespace insmc::app {

/// A file the command reads (`--records`, `--input`, `--bounds`,
/// `--config`, `--from`, `--resume`): no output may be one of them.
struct InputFile {
  std::string option, path;
};
/// The input files named in `vm`.
std::vector<InputFile> input_files(const po::variables_map& vm);

/// An output folder (`--out DIR`), checked and locked.
class OutputFolderOption {
 public:
  /// `command`: the subcommand (recorded in the set's manifest);
  /// `expected_files`: the names the set will hold (each checked now: not
  /// a folder, link or device, and not one of `inputs`).
  OutputFolderOption(std::string option, std::string path, const std::string& command,
                     const std::vector<std::string>& expected_files, const std::vector<InputFile>& inputs);
  /// Writes the whole set (a failure the user can fix: InputError).
  void write(const mc::OutputSetFiles& files);

 private:
  std::string option_, text_;
  std::vector<std::string> expected_;
  std::optional<mc::OutputFolder> folder_;
};

/// The folder of option "out" when it was given, checked and locked for
/// the set `outline` names; gnuplot must be there when the set has figures,
/// or the command stops now (exit 2, naming the package), before any work.
/// `read_before`: inputs of an earlier parse that `vm` no longer names (the
/// --from or --resume file a command line was rebuilt from).
/// --out's help: "folder for <the outline's set> (created if needed)".
std::string out_folder_help(const mc::ReportOutline& outline);

std::optional<OutputFolderOption> prepare_report_folder(const po::variables_map& vm, const mc::ReportOutline& outline,
                                                        const std::vector<InputFile>& read_before = {});

/// One output file (`--out FILE`, `--checkpoint FILE`), checked and locked;
/// it may not be one of the command's input files (`--checkpoint` may be
/// the file of `--resume`, which it continues).
class OutputFileOption {
 public:
  OutputFileOption(std::string option, std::string path, const std::vector<InputFile>& inputs);
  /// Replaces the file atomically (a failure the user can fix: InputError).
  void write(std::string_view contents) const;

 private:
  std::string option_, text_;
  std::optional<mc::OutputFile> file_;
};

}  // namespace insmc::app
