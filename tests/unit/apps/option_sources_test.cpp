// The options run.json keeps in settings.arguments (explicit_arguments,
// apps/option_sources.h): each option type an insmc option has comes back
// as the `--name=value` it was given as; a type the file cannot keep is a
// programming error caught before the study runs.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "apps/option_sources.h"

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

}  // namespace
}  // namespace insmc::app
