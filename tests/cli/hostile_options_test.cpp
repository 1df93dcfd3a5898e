// Every option of every subcommand, read from its own --help: a value that
// is not one it takes, alone or as the last element of a comma list, ends
// with exit 2 and one line naming the option, before any work (no file
// written, within seconds, bounded memory). An option whose value is never
// checked, or whose list is silently cut to its first value, fails here
// whatever subcommand grows it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "tests/cli/run_program.h"

namespace insmc::testing {
namespace {

struct OptionHelp {
  std::string name;
  bool takes_value = false;
  std::string default_value;  ///< empty: none
};

/// The options `insmc <command> --help` lists.
std::vector<OptionHelp> options_of(const std::string& command) {
  const ProgramResult r = run_insmc(command + " --help");
  EXPECT_EQ(r.exit_code, 0) << command;
  std::vector<OptionHelp> out;
  const std::regex line(R"(^  --([a-z0-9-]+)(?:,? ?-[a-z])?( arg)?(?: \(=([^)]*)\))?)");
  std::istringstream in(r.out);
  for (std::string text; std::getline(in, text);) {
    std::smatch m;
    if (std::regex_search(text, m, line)) out.push_back({m[1].str(), m[2].matched, m[3].matched ? m[3].str() : ""});
  }
  return out;
}

/// The least a subcommand needs besides the option under test, so that the
/// option's own check is what answers (files in `dir`).
std::string required_of(const std::string& command, const std::string& dir) {
  if (command == "gap" || command == "compensate") return " --records " + dir + "/runs.csv";
  if (command == "check") return " --bounds " + dir + "/bounds.txt";
  if (command == "simulate") return " --out " + dir + "/sim.csv";
  if (command == "noise") return " --input " + dir + "/imu.csv --rate 100Hz";
  if (command == "import-imu") return " --input " + dir + "/imu.csv --rate 100Hz --latitude 51deg --out " + dir + "/imp.csv";
  return "";
}

/// Options whose value is free text or a path insmc would create or write:
/// any value is taken (a garbage one would name a new file).
const std::set<std::string> kFreeText = {"out", "checkpoint", "time-column"};

void write_inputs(const std::string& dir) {
  ASSERT_EQ(run_insmc("simulate --runs 5 --nav-duration 10min --out " + dir + "/runs.csv").exit_code, 0);
  std::ofstream(dir + "/bounds.txt") << "scheme=none system=1 axis=horizontal t_min=84 rms_m<=1e7\n";
  std::ofstream imu(dir + "/imu.csv");
  imu << "gyro_x_dps,gyro_y_dps,gyro_z_dps,acc_x_g,acc_y_g,acc_z_g\n";
  for (int k = 0; k < 1000; ++k) imu << "0.001,0.002,0.003,0.0001,0.0002,-1\n";
}

/// Whether `message` names --`option` itself (not an option whose name
/// starts with it, as --seed does --seeds).
bool names_option(const std::string& message, const std::string& option) {
  const std::string named = "--" + option;
  for (std::size_t at = message.find(named); at != std::string::npos; at = message.find(named, at + 1)) {
    const std::size_t end = at + named.size();
    if (end == message.size() || !(std::isalnum(static_cast<unsigned char>(message[end])) || message[end] == '-'))
      return true;
  }
  return false;
}

void expect_refused_at_once(const std::string& args, const std::string& option, const std::string& dir) {
  const ProgramResult r = run_limited(args, 60);
  EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << args << "\n" << r.err;
  EXPECT_TRUE(names_option(r.err, option)) << args << "\n" << r.err;
  EXPECT_LT(r.peak_rss_kb, 1 << 20) << args;
  for (const char* written : {"sim.csv", "imp.csv"})
    EXPECT_FALSE(std::filesystem::exists(std::filesystem::path(dir) / written)) << args;
}

TEST(HostileOptions, EveryValueOfEveryOptionOfEveryCommandIsCheckedBeforeTheWork) {
  TempDir dir;
  write_inputs(dir.str());
  int checked = 0;
  for (const std::string command : {"run", "covariance", "rank", "check", "tables", "simulate", "import-imu", "noise",
                                    "gap", "gap-validate", "compensate", "effects", "params", "bench"}) {
    const std::string required = required_of(command, dir.str());
    for (const OptionHelp& o : options_of(command)) {
      if (!o.takes_value || kFreeText.count(o.name)) continue;
      // The option's own name is what the message must show (Boost names
      // the option of a value it cannot convert the same way).
      const std::string named = o.name;
      expect_refused_at_once(command + required + " --" + o.name + "=@garbage@", named, dir.str());
      if (!o.default_value.empty())
        expect_refused_at_once(command + required + " --" + o.name + "=" + o.default_value + ",@garbage@", named,
                               dir.str());
      ++checked;
    }
  }
  EXPECT_GT(checked, 80) << "the --help parsing found too few options";
}

TEST(HostileOptions, APercentPlaceholderInAnArgumentIsRefusedNotLoopedOn) {
  // Boost substitutes %option%, %value%, %original_token% into its messages
  // until none is left: these once hung insmc (found by fuzz_options).
  for (const std::string args :
       {"run --x%original_token%y", "gap --alpha=%value%", "run --threads=%value%x", "run --%canonical_option%"}) {
    const ProgramResult r = run_limited(args, 10);
    EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.err;
    EXPECT_NE(r.err.find("it holds a '%'"), std::string::npos) << args << "\n" << r.err;
  }
}

TEST(HostileOptions, APercentValueAndATooLargeCountSayWhatIsAllowed) {
  const ProgramResult percent = run_insmc("run --confidence 95%");
  EXPECT_EQ(percent.exit_code, 2);
  EXPECT_NE(percent.err.find("--confidence = 95%: no '%' in a value (95% is 0.95)"),
            std::string::npos)
      << percent.err;
  for (const std::string seed : {"1e20", "99999999999999999999"}) {
    const ProgramResult large = run_insmc("run --seed " + seed);
    EXPECT_EQ(large.exit_code, 2);
    EXPECT_NE(large.err.find("--seed = " + seed + ": is too large: a whole number up to 2^53"), std::string::npos)
        << large.err;
  }
}

TEST(HostileOptions, AMisspelledOptionOrEffectNameGetsTheNameMeant) {
  const ProgramResult option = run_insmc("gap --recrods x.csv");
  EXPECT_EQ(option.exit_code, 2);
  EXPECT_NE(option.err.find("unrecognised option '--recrods' (did you mean --records?)"), std::string::npos)
      << option.err;
  const ProgramResult effect = run_insmc("simulate --effect angle_randomwalk --out x.csv");
  EXPECT_EQ(effect.exit_code, 2);
  EXPECT_NE(effect.err.find("unknown effect (did you mean angle_random_walk?)"), std::string::npos) << effect.err;
  // Nothing close: no guess.
  const ProgramResult far = run_insmc("run --gyro-drift-bound 1meru");
  EXPECT_EQ(far.exit_code, 2);
  EXPECT_EQ(far.err.find("did you mean"), std::string::npos) << far.err;
}

TEST(HostileOptions, AUnitInItsUsualSpellingIsTakenForTheOneInsmcNamesIt) {
  // deg/h for degph, as data sheets write it; the same study bit for bit.
  TempDir dir;
  const ProgramResult typed = run_insmc("run --samples 200 --quiet --bound gyro_drift=3deg/h --out " + dir.str() + "/a");
  const ProgramResult named = run_insmc("run --samples 200 --quiet --bound gyro_drift=3degph --out " + dir.str() + "/b");
  ASSERT_EQ(typed.exit_code, 0) << typed.err;
  ASSERT_EQ(named.exit_code, 0) << named.err;
  EXPECT_EQ(typed.out, named.out);
}

}  // namespace
}  // namespace insmc::testing
