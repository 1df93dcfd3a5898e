#include "montecarlo/report/output_manifest.h"

#include <algorithm>

namespace insmc::mc {

namespace {

constexpr std::string_view kFirstLine = "insmc output set 1";

bool valid_name(std::string_view name) {
  return !name.empty() && name != "." && name != ".." && name.find('/') == std::string_view::npos &&
         name.find('\n') == std::string_view::npos && name.find('\0') == std::string_view::npos;
}

}  // namespace

std::string render_manifest(const OutputManifest& manifest) {
  std::vector<std::string> files = manifest.files;
  std::sort(files.begin(), files.end());
  std::string out = std::string(kFirstLine) + "\ncommand " + manifest.command + "\n";
  for (const std::string& f : files) out += "file " + f + "\n";
  return out;
}

std::optional<OutputManifest> parse_manifest(std::string_view text) {
  std::vector<std::string_view> lines;
  while (!text.empty()) {
    const std::size_t end = text.find('\n');
    if (end == std::string_view::npos) return std::nullopt;  // a whole manifest ends with a newline
    lines.push_back(text.substr(0, end));
    text.remove_prefix(end + 1);
  }
  if (lines.size() < 2 || lines[0] != kFirstLine || lines[1].substr(0, 8) != "command ") return std::nullopt;
  OutputManifest m;
  m.command = std::string(lines[1].substr(8));
  if (!valid_name(m.command)) return std::nullopt;
  for (std::size_t i = 2; i < lines.size(); ++i) {
    if (lines[i].substr(0, 5) != "file ") return std::nullopt;
    const std::string_view name = lines[i].substr(5);
    if (!valid_name(name) || name == kManifestName) return std::nullopt;
    m.files.emplace_back(name);
  }
  if (!std::is_sorted(m.files.begin(), m.files.end()) ||
      std::adjacent_find(m.files.begin(), m.files.end()) != m.files.end())
    return std::nullopt;
  return m;
}

}  // namespace insmc::mc
