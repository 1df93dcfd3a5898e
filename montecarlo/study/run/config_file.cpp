#include "montecarlo/study/run/config_file.h"

#include <fmt/format.h>

#include "lib/common/input_error.h"
#include "lib/common/input_text.h"

namespace insmc::mc {
namespace {

std::string quote(std::string_view text) { return fmt::format("'{}'", echo_input(text)); }

}  // namespace

void read_config_text(std::string_view text, std::string_view source,
                      const std::function<std::string(const ConfigEntry&)>& take) {
  const std::string name = echo_input(source, 256);
  std::size_t line_number = 0;
  const auto fail = [&](const std::string& message) {
    throw InputError(fmt::format("{}:{}: {}", name, line_number, message));
  };
  if (text.starts_with("\xEF\xBB\xBF")) text.remove_prefix(3);  // UTF-8 byte-order mark
  std::string prefix;                                           // "section." after a [section] line
  for (std::size_t pos = 0; pos < text.size();) {
    ++line_number;
    const std::size_t nl = text.find('\n', pos);
    const std::size_t end = nl == std::string_view::npos ? text.size() : nl;
    if (end - pos > kMaxConfigLineBytes)
      fail(fmt::format("line of {} bytes: a --config line may hold at most {} bytes", end - pos, kMaxConfigLineBytes));
    std::string_view line = text.substr(pos, end - pos);
    pos = end + 1;
    if (const std::size_t hash = line.find('#'); hash != std::string_view::npos) line = line.substr(0, hash);
    line = trim(line);
    if (line.empty()) continue;
    if (line.front() == '[') {
      if (line.back() != ']' || line.size() < 3) fail(fmt::format("section line {} is not '[name]'", quote(line)));
      prefix = std::string(trim(line.substr(1, line.size() - 2))) + ".";
      continue;
    }
    const std::size_t eq = line.find('=');
    if (eq == std::string_view::npos)
      fail(fmt::format("{} is not 'key = value' (e.g. samples = 100000)", quote(line)));
    ConfigEntry entry{prefix + std::string(trim(line.substr(0, eq))), std::string(trim(line.substr(eq + 1))),
                      line_number};
    if (entry.key == prefix) fail(fmt::format("empty key before '=' in {}", quote(line)));
    if (const std::string why = take(entry); !why.empty()) fail(why);
  }
}

std::string read_config_file(const std::string& path) {
  return read_file_capped(path, kMaxConfigFileBytes, "--config file");
}

}  // namespace insmc::mc
