#pragma once
/// A command's report: the files of its `--out` set and what stdout shows
/// in each `--format`. A command names its set before the work
/// (ReportOutline), so that the folder is checked and locked, and a format
/// it does not offer refused, before any of it; the report it returns
/// after the work holds those names and no other. One writer in apps/
/// (apps/report_output.h) writes any report in any format.
#include <array>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "montecarlo/report/output_set.h"
#include "montecarlo/report/plot/gnuplot.h"

namespace insmc::mc {

enum class ReportFormat { kMarkdown, kCsv, kJson };
inline constexpr std::array<ReportFormat, 3> kReportFormats{ReportFormat::kMarkdown, ReportFormat::kCsv,
                                                             ReportFormat::kJson};
/// "markdown", "csv", "json".
std::string_view format_name(ReportFormat format);

/// What a command's set holds and what its stdout offers, known before the
/// work.
struct ReportOutline {
  std::string command;                    ///< the subcommand (the set's manifest records it)
  std::vector<std::string> files;         ///< the data files, by name
  std::vector<std::string> figure_stems;  ///< each drawn to <stem>.gp, .svg, .png
  std::vector<ReportFormat> formats{kReportFormats.begin(), kReportFormats.end()};

  /// Every name the set may hold: the files, then each figure's three.
  std::vector<std::string> set_names() const;
  bool offers(ReportFormat format) const;
  /// The formats offered, for a message: "markdown or json".
  std::string offered_text() const;
  /// The set, for a help text: "a.md, b.csv and the figure c (.gp, .svg,
  /// .png, drawn by gnuplot)".
  std::string set_text() const;
};

/// The compact summary a command prints in markdown instead of its full
/// tables (docs/outputs.md), and the line under it saying where the rest is.
struct ReportSummary {
  std::string text;  ///< stdout in markdown without --full
  /// The line under it, and under the full markdown when --out is given
  /// (docs/outputs.md); `out_folder`: --out's folder when given.
  std::function<std::string(const std::optional<std::string>& out_folder)> where_the_rest_is;
};

/// Names for a message: "a", "a and b", "a, b and c" (`conjunction` "or":
/// "a, b or c").
std::string listed(const std::vector<std::string>& names, std::string_view conjunction = "and");

/// The line under a summary whose full tables are `files`: their paths in
/// --out's folder, or how to get them.
std::string full_tables_line(const std::string& command, const std::vector<std::string>& files,
                             const std::optional<std::string>& out_folder);

class Report {
 public:
  explicit Report(ReportOutline outline);

  /// A file of the set: `name` is one of the outline's files, given once.
  Report& file(const std::string& name, std::string contents);
  /// A figure of the set: `stem` is one of the outline's figure stems;
  /// `draw` runs gnuplot only when the set is written (stdout alone needs
  /// no gnuplot).
  Report& figure(const std::string& stem, std::function<RenderedFigure()> draw);
  /// What stdout shows in `format`, one the outline offers.
  Report& shown(ReportFormat format, std::string text);
  /// Stdout in `format` is the set's file `name`, as written (not a copy).
  Report& shown_file(ReportFormat format, std::string name);
  /// Stdout in markdown without --full, for a command with a compact summary.
  Report& summary(ReportSummary summary);

  const ReportOutline& outline() const { return outline_; }
  /// The set: the files in the order given, then each figure drawn.
  OutputSetFiles draw_set() const;
  /// The text of one of the set's files (an internal error when absent).
  const std::string& file_text(std::string_view name) const;
  /// What stdout shows in `format` (given for every format offered).
  const std::string& shown(ReportFormat format) const;
  const std::optional<ReportSummary>& summary() const { return summary_; }

 private:
  ReportOutline outline_;
  OutputSetFiles files_;
  std::vector<std::pair<std::string, std::function<RenderedFigure()>>> figures_;
  std::array<std::optional<std::string>, kReportFormats.size()> shown_;
  /// For a format shown as one of the files: that file's name.
  std::array<std::optional<std::string>, kReportFormats.size()> shown_file_;
  std::optional<ReportSummary> summary_;
};

}  // namespace insmc::mc
