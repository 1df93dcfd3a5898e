// The options run.json keeps in settings.arguments (explicit_arguments,
// apps/option_sources.h): each option type an insmc option has comes back
// as the `--name=value` it was given as; a type the file cannot keep is a
// programming error caught before the study runs.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "apps/option_sources.h"
#include "lib/common/input_error.h"

namespace insmc::app {
namespace {

po::variables_map parse(const po::options_description& opts, std::vector<std::string> args) {
  po::variables_map vm;
  po::store(po::command_line_parser(args).options(opts).run(), vm);
  po::notify(vm);
  return vm;
}

TEST(RunFile, EveryOptionTypeComesBackAsItsCanonicalArgument) {
  po::options_description opts;
  opts.add_options()("text", po::value<std::string>())("list", po::value<std::vector<std::string>>()->composing())(
      "number", po::value<double>())("count", po::value<int>())("switch", po::bool_switch())(
      "defaulted", po::value<std::string>()->default_value("x"))("out", po::value<std::string>());
  const po::variables_map vm = parse(opts, {"--text", "5min", "--list", "a=1", "--list", "b=2", "--number", "0.1",
                                            "--count", "7", "--switch", "--out", "/tmp/x"});
  const Args expected = {"--text=5min", "--list=a=1", "--list=b=2", "--number=0.1", "--count=7", "--switch"};
  EXPECT_EQ(explicit_arguments(vm, opts, {"out"}), expected);
  // A switch not given and a defaulted value are not arguments.
  EXPECT_TRUE(explicit_arguments(parse(opts, {}), opts, {}).empty());
}

TEST(RunFile, AnOptionTypeRunJsonCannotKeepIsRefused) {
  po::options_description opts;
  opts.add_options()("size", po::value<unsigned long>());
  EXPECT_THROW(explicit_arguments(parse(opts, {"--size", "3"}), opts, {}), std::logic_error);
}

TEST(RunFile, ArgumentsAreOptionsByNameNeverACommandLine) {
  po::options_description opts;
  opts.add_options()("samples", po::value<std::string>())("bound", po::value<std::vector<std::string>>()->composing())(
      "quick", po::bool_switch())("out", po::value<std::string>())("help,h", "");
  const auto error_of = [&](const std::vector<std::string>& elements) -> std::string {
    try {
      run_file_options(elements, opts, "--from", "d/run.json", "settings.arguments");
    } catch (const InputError& e) {
      return e.what();
    }
    return "(accepted)";
  };
  const po::parsed_options kept = run_file_options({"--samples=5", "--bound=a=1", "--bound=b=2", "--quick"}, opts,
                                                   "--from", "d/run.json", "settings.arguments");
  po::variables_map vm;
  po::store(kept, vm);
  EXPECT_EQ(vm["samples"].as<std::string>(), "5");
  EXPECT_EQ(vm["bound"].as<std::vector<std::string>>(), (std::vector<std::string>{"a=1", "b=2"}));
  EXPECT_TRUE(vm["quick"].as<bool>());
  // A `--` ends the options of a command line; in a file it is refused, so
  // what follows it is never taken as typed.
  EXPECT_EQ(error_of({"--samples=5", "--", "--out=/x"}),
            "--from = d/run.json: settings.arguments[1] = '--' is not an option by name (each element is "
            "--NAME=VALUE, or --NAME for a switch, never a command line)");
  EXPECT_EQ(error_of({"--out=/x"}),
            "--from = d/run.json: settings.arguments[0] holds --out, which names where insmc writes: a file of "
            "options may not; give it on the command line");
  for (const char* e : {"-h", "x", "---out=/x", "--=1", ""})
    EXPECT_NE(error_of({e}).find("is not an option by name"), std::string::npos) << e;
  EXPECT_NE(error_of({"--sam=5"}).find("names an unknown option 'sam'"), std::string::npos);
  EXPECT_NE(error_of({"--quick=yes"}).find("gives --quick a value; it is a switch"), std::string::npos);
  EXPECT_NE(error_of({"--samples"}).find("gives --samples no value"), std::string::npos);
  EXPECT_NE(error_of({"--samples=1", "--samples=2"}).find("[1] gives --samples twice (first in [0])"), std::string::npos);
}

}  // namespace
}  // namespace insmc::app
