#include "apps/run_file.h"

#include <algorithm>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "lib/common/input_error.h"
#include "lib/common/input_text.h"

namespace insmc::app {

Args explicit_arguments(const po::variables_map& vm, const po::options_description& options,
                        const std::vector<std::string>& drop) {
  Args out;
  for (const auto& option : options.options()) {
    const std::string& name = option->long_name();
    if (!vm.count(name) || vm[name].defaulted() || std::find(drop.begin(), drop.end(), name) != drop.end()) continue;
    const boost::any& v = vm[name].value();
    if (const auto* s = boost::any_cast<std::string>(&v)) {
      out.push_back(fmt::format("--{}={}", name, *s));
    } else if (const auto* list = boost::any_cast<std::vector<std::string>>(&v)) {
      for (const std::string& e : *list) out.push_back(fmt::format("--{}={}", name, e));
    } else if (const auto* d = boost::any_cast<double>(&v)) {
      out.push_back(fmt::format("--{}={}", name, *d));  // shortest exact round trip
    } else if (const auto* i = boost::any_cast<int>(&v)) {
      out.push_back(fmt::format("--{}={}", name, *i));
    } else if (const auto* b = boost::any_cast<bool>(&v)) {
      if (*b) out.push_back("--" + name);
    } else {
      throw std::logic_error("option --" + name + " has a type run.json cannot keep");
    }
  }
  return out;
}

Args run_arguments_from_json(std::string_view text, std::string_view source) {
  const std::string where(source);
  const nlohmann::json j = nlohmann::json::parse(text.begin(), text.end(), nullptr, /*allow_exceptions=*/false);
  if (j.is_discarded()) throw InputError("--from", echo_input(where), "is not JSON (a run.json written by insmc run)");
  const auto settings = j.is_object() ? j.find("settings") : j.end();
  const bool has = j.is_object() && settings != j.end() && settings->is_object() &&
                   settings->contains("arguments") && (*settings)["arguments"].is_array();
  if (!has)
    throw InputError("--from", echo_input(where),
                     "has no settings.arguments array (a run.json of insmc run 0.1.0 or later)");
  const nlohmann::json& list = (*settings)["arguments"];
  if (list.size() > kMaxRunArguments)
    throw InputError("--from", echo_input(where), fmt::format("settings.arguments holds {} values (at most {})",
                                                               list.size(), kMaxRunArguments));
  Args out;
  for (std::size_t i = 0; i < list.size(); ++i) {
    if (!list[i].is_string() || list[i].get_ref<const std::string&>().rfind("--", 0) != 0 ||
        list[i].get_ref<const std::string&>().size() > kMaxRunArgumentBytes)
      throw InputError("--from", echo_input(where),
                       fmt::format("settings.arguments[{}] must be an option \"--name=value\" of at most {} bytes", i,
                                   kMaxRunArgumentBytes));
    out.push_back(list[i].get<std::string>());
  }
  return out;
}

Args read_run_arguments(const std::string& path) {
  return run_arguments_from_json(read_file_capped(path, kMaxRunJsonBytes, "--from file"), path);
}

}  // namespace insmc::app
