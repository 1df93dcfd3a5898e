// Every command's --help ends with an example, and the examples that need
// no file of the user's run as printed (apps/help_examples.h).
#include <gtest/gtest.h>

#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "tests/cli/run_program.h"

namespace insmc::testing {
namespace {

const char* const kCommands[] = {"run",        "covariance", "rank",   "check", "tables",  "simulate", "import-imu",
                                 "noise",      "gap",        "gap-validate", "compensate", "effects", "params", "bench"};

std::vector<std::string> examples_of(const std::string& help) {
  std::vector<std::string> out;
  std::istringstream in(help);
  std::string line;
  bool after = false;
  while (std::getline(in, line)) {
    if (line == "Example:" || line == "Examples:") after = true;
    else if (after && line.rfind("  insmc ", 0) == 0) out.push_back(line.substr(8));
  }
  return out;
}

TEST(HelpExamples, EveryCommandsHelpEndsWithAnExampleOfItself) {
  for (const std::string command : kCommands) {
    const ProgramResult r = run_insmc(command + " --help");
    ASSERT_EQ(r.exit_code, 0) << command;
    const std::vector<std::string> examples = examples_of(r.out);
    ASSERT_FALSE(examples.empty()) << command << ":\n" << r.out;
    for (const std::string& e : examples) EXPECT_EQ(e.rfind(command + " ", 0), 0U) << e;
  }
}

TEST(HelpExamples, TheExamplesWithoutAUsersFileRunAsPrinted) {
  TempDir dir;
  for (const std::string command : {"covariance", "tables", "simulate", "effects", "params"}) {
    for (const std::string& e : examples_of(run_insmc(command + " --help").out)) {
      const std::string line = std::regex_replace(e, std::regex("--out (\\S+)"), "--out " + dir.str() + "/$1");
      const ProgramResult r = run_insmc(line + " > /dev/null");
      EXPECT_EQ(r.exit_code, 0) << line << "\n" << r.err;
    }
  }
}

}  // namespace
}  // namespace insmc::testing
