// The options of a --config INI file (apps/config_options.h, over the reader
// montecarlo/study/run/config_file.h): file:line and key in every message, BOM,
// duplicates, escaped echoes, caps.
#include "apps/config_options.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "lib/common/input_error.h"
#include "montecarlo/study/run/config_file.h"

namespace insmc::app {
namespace {

namespace po = boost::program_options;

po::options_description test_options() {
  po::options_description d("Options");
  d.add_options()("samples", po::value<std::uint64_t>())("latitude", po::value<std::string>())(
      "bound", po::value<std::vector<std::string>>()->composing())("study.seed", po::value<int>());
  return d;
}

std::string error_of(const std::string& text) {
  const auto d = test_options();
  try {
    po::variables_map vm;
    po::store(parse_config_text(text, "study.ini", d), vm);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(accepted)";
}

TEST(ConfigOptions, ReadsKeysSectionsCommentsAndABom) {
  const auto d = test_options();
  po::variables_map vm;
  po::store(parse_config_text("\xEF\xBB\xBF# study\nsamples = 1000\r\n\nbound = a=1 # first\nbound=b=2\n[study]\nseed=7\n",
                              "study.ini", d),
            vm);
  EXPECT_EQ(vm["samples"].as<std::uint64_t>(), 1000u);
  EXPECT_EQ(vm["bound"].as<std::vector<std::string>>(), (std::vector<std::string>{"a=1", "b=2"}));
  EXPECT_EQ(vm["study.seed"].as<int>(), 7);
}

TEST(ConfigOptions, CommandLineWins) {
  const auto d = test_options();
  po::variables_map vm;
  const std::vector<std::string> args = {"--samples", "5"};
  po::store(po::command_line_parser(args).options(d).run(), vm);
  po::store(parse_config_text("samples = 1000\n", "study.ini", d), vm);
  EXPECT_EQ(vm["samples"].as<std::uint64_t>(), 5u);
}

TEST(ConfigOptions, MessagesNameFileLineAndKey) {
  EXPECT_EQ(error_of("samples = 10\nsampels = 5\n"),
            "study.ini:2: unknown option 'sampels' (the keys are the long option names, without --)");
  EXPECT_EQ(error_of("\n\nsamples = many\n"), "study.ini:3: samples = 'many': not a value this option takes (see --help)");
  EXPECT_EQ(error_of("samples = 1\nlatitude=1deg\nsamples = 2\n"), "study.ini:3: samples given twice (first on line 1)");
  EXPECT_EQ(error_of("just words\n"), "study.ini:1: 'just words' is not 'key = value' (e.g. samples = 100000)");
  EXPECT_EQ(error_of(" = 5\n"), "study.ini:1: empty key before '=' in '= 5'");
  EXPECT_EQ(error_of("[study\n"), "study.ini:1: section line '[study' is not '[name]'");
}

TEST(ConfigOptions, EchoesAreEscapedAndCut) {
  const std::string e = error_of("samples = \x1b[2J" + std::string(1000, '9') + "x\n");
  EXPECT_EQ(e, "study.ini:1: samples = '\\x1B[2J" + std::string(36, '9') +
                   "\u2026(1005 bytes)': not a value this option takes (see --help)");
  const std::string k = error_of(std::string("bad\x01key = 1\n"));
  EXPECT_EQ(k, "study.ini:1: unknown option 'bad\\x01key' (the keys are the long option names, without --)");
}

TEST(ConfigOptions, CapsOnLinesAndEntries) {
  EXPECT_EQ(error_of("latitude = " + std::string(mc::kMaxConfigLineBytes, '1') + "\n"),
            fmt::format("study.ini:1: line of {} bytes: a --config line may hold at most {} bytes",
                        mc::kMaxConfigLineBytes + 11, mc::kMaxConfigLineBytes));
  std::string many;
  for (std::size_t i = 0; i <= kMaxConfigEntries; ++i) many += "bound = x\n";
  EXPECT_EQ(error_of(many), fmt::format("study.ini:{}: more than {} options: a --config file may hold at most {}",
                                        kMaxConfigEntries + 1, kMaxConfigEntries, kMaxConfigEntries));
}

}  // namespace
}  // namespace insmc::app
