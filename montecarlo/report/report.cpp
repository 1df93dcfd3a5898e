#include "montecarlo/report/report.h"

#include <algorithm>
#include <filesystem>
#include <fmt/format.h>
#include <fmt/ranges.h>

#include "lib/common/assert.h"

namespace insmc::mc {

std::string_view format_name(ReportFormat format) {
  switch (format) {
    case ReportFormat::kMarkdown: return "markdown";
    case ReportFormat::kCsv: return "csv";
    case ReportFormat::kJson: return "json";
  }
  return "";
}

std::vector<std::string> ReportOutline::set_names() const {
  std::vector<std::string> names = files;
  for (const std::string& stem : figure_stems)
    for (std::string& name : figure_file_names(stem)) names.push_back(std::move(name));
  return names;
}

bool ReportOutline::offers(ReportFormat format) const {
  return std::find(formats.begin(), formats.end(), format) != formats.end();
}

std::string ReportOutline::offered_text() const {
  std::vector<std::string> names;
  for (const ReportFormat format : formats) names.emplace_back(format_name(format));
  return listed(names, "or");
}

std::string listed(const std::vector<std::string>& names, std::string_view conjunction) {
  std::string text;
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (i > 0) text += i + 1 == names.size() ? fmt::format(" {} ", conjunction) : std::string(", ");
    text += names[i];
  }
  return text;
}

std::string ReportOutline::set_text() const {
  if (figure_stems.empty()) return listed(files);
  return fmt::format("{}{}the figure{} {} (.gp, .svg, .png, drawn by gnuplot)", fmt::join(files, ", "),
                     files.empty() ? "" : " and ", figure_stems.size() > 1 ? "s" : "", listed(figure_stems));
}

std::string full_tables_line(const std::string& command, const std::vector<std::string>& files,
                             const std::optional<std::string>& out_folder) {
  if (out_folder) {
    const std::filesystem::path out(*out_folder);
    std::string names;
    for (const std::string& f : files) names += fmt::format("{}{}", names.empty() ? "" : ", ", (out / f).string());
    return fmt::format("Full tables (every axis and time): {}\n", names);
  }
  return fmt::format("Full tables (every axis and time): insmc {} --full, or --out DIR for {}, or --format csv\n",
                     command, listed(files));
}

Report::Report(ReportOutline outline) : outline_(std::move(outline)) {}

Report& Report::file(const std::string& name, std::string contents) {
  INSMC_ASSERT(std::find(outline_.files.begin(), outline_.files.end(), name) != outline_.files.end(),
               "{} writes {}, which its outline does not name", outline_.command, name);
  INSMC_ASSERT(std::none_of(files_.begin(), files_.end(), [&](const auto& f) { return f.first == name; }),
               "{} writes {} twice", outline_.command, name);
  files_.emplace_back(name, std::move(contents));
  return *this;
}

Report& Report::figure(const std::string& stem, std::function<RenderedFigure()> draw) {
  INSMC_ASSERT(std::find(outline_.figure_stems.begin(), outline_.figure_stems.end(), stem) != outline_.figure_stems.end(),
               "{} draws {}, which its outline does not name", outline_.command, stem);
  figures_.emplace_back(stem, std::move(draw));
  return *this;
}

OutputSetFiles Report::draw_set() const {
  OutputSetFiles set = files_;
  for (const auto& [stem, draw] : figures_)
    for (auto& f : figure_files(stem, draw())) set.push_back(std::move(f));
  return set;
}

Report& Report::shown(ReportFormat format, std::string text) {
  INSMC_ASSERT(outline_.offers(format), "{} shows {}, which its outline does not offer", outline_.command,
               format_name(format));
  shown_[static_cast<std::size_t>(format)] = std::move(text);
  return *this;
}

Report& Report::shown_file(ReportFormat format, std::string name) {
  INSMC_ASSERT(outline_.offers(format), "{} shows {}, which its outline does not offer", outline_.command,
               format_name(format));
  INSMC_ASSERT(std::find(outline_.files.begin(), outline_.files.end(), name) != outline_.files.end(),
               "{} shows {}, which its outline does not name", outline_.command, name);
  shown_file_[static_cast<std::size_t>(format)] = std::move(name);
  return *this;
}

Report& Report::summary(ReportSummary summary) {
  summary_ = std::move(summary);
  return *this;
}

const std::string& Report::file_text(std::string_view name) const {
  const auto it = std::find_if(files_.begin(), files_.end(), [&](const auto& f) { return f.first == name; });
  INSMC_ASSERT(it != files_.end(), "{} has no file {}", outline_.command, name);
  return it->second;
}

const std::string& Report::shown(ReportFormat format) const {
  if (const auto& name = shown_file_[static_cast<std::size_t>(format)]) return file_text(*name);
  const auto& text = shown_[static_cast<std::size_t>(format)];
  INSMC_ASSERT(text.has_value(), "{} shows nothing in {}", outline_.command, format_name(format));
  return *text;
}

}  // namespace insmc::mc
