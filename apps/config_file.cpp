#include "apps/config_file.h"

#include "apps/option_sources.h"

#include <fmt/format.h>

#include <map>
#include <vector>

#include "lib/common/input_error.h"
#include "lib/common/input_text.h"

namespace insmc::app {
namespace {

namespace po = boost::program_options;



std::string quote(std::string_view text) { return fmt::format("'{}'", echo_input(text)); }

}  // namespace

po::parsed_options parse_config_text(std::string_view text, std::string_view source,
                                     const po::options_description& options) {
  const std::string name = echo_input(source, 256);
  std::size_t line_number = 0;
  const auto fail = [&](const std::string& message) {
    throw InputError(fmt::format("{}:{}: {}", name, line_number, message));
  };
  if (text.starts_with("\xEF\xBB\xBF")) text.remove_prefix(3);  // UTF-8 byte-order mark
  po::parsed_options parsed(&options);
  std::map<std::string, std::size_t> first_line;  // of each option that may be given once
  std::string prefix;                              // "section." after a [section] line
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
    const std::string key = prefix + std::string(trim(line.substr(0, eq)));
    const std::string value(trim(line.substr(eq + 1)));
    if (key == prefix) fail(fmt::format("empty key before '=' in {}", quote(line)));
    const po::option_description* d = options.find_nothrow(key, /*approx=*/false);
    if (d == nullptr) fail(fmt::format("unknown option {} (the keys are the long option names, without --)", quote(key)));
    if (const std::string why = refused_from(d->long_name(), OptionSource::kConfigFile); !why.empty())
      fail(fmt::format("{}: {}", key, why));
    if (parsed.options.size() >= kMaxConfigEntries)
      fail(fmt::format("more than {} options: a --config file may hold at most {}", kMaxConfigEntries,
                       kMaxConfigEntries));
    if (!d->semantic()->is_composing()) {
      const auto [it, inserted] = first_line.emplace(key, line_number);
      if (!inserted) fail(fmt::format("{} given twice (first on line {})", key, it->second));
    }
    // Each value on its own first, so that a bad one is named with its line.
    po::parsed_options one(&options);
    one.options.emplace_back(key, std::vector<std::string>{value});
    try {
      po::variables_map scratch;
      po::store(one, scratch);
    } catch (const po::error&) {
      fail(fmt::format("{} = {}: not a value this option takes (see --help)", key, quote(value)));
    }
    parsed.options.emplace_back(key, std::vector<std::string>{value});
  }
  return parsed;
}

void store_config_file(const std::string& path, const po::options_description& options, po::variables_map& vm) {
  const std::string text = read_file_capped(path, kMaxConfigFileBytes, "--config file");
  po::store(parse_config_text(text, path, options), vm);
}

}  // namespace insmc::app
