// A subcommand added by this test alone (apps/README.md, "Adding a
// subcommand"): one function that parses its options and returns its
// report, and one entry in a list. Dispatch gives it what every
// subcommand has: --help and the usage line, --format checked against its
// report's outline before the work, --out written as a whole set, and its
// failures as one line on stderr with exit code 2 (bad input) or 3 (defect).
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "apps/cli_common.h"
#include "apps/dispatch.h"
#include "apps/output_paths.h"
#include "apps/report_output.h"
#include "apps/stdout_choice.h"
#include "lib/common/input_error.h"

namespace insmc::app {
namespace {

/// echo: prints its --text as markdown or csv; --fail makes it a defect.
int cmd_echo(const Args& args) {
  po::options_description opts("Options");
  opts.add_options()("text", po::value<std::string>()->default_value("hello"), "what to print")(
      "format", po::value<std::string>()->default_value("markdown"), "markdown or csv")(
      "out", po::value<std::string>(), "folder for echo.md and echo.csv")("fail", po::bool_switch(), "a defect");
  add_stdout_switches(opts, "echo.md");
  const auto vm = parse_args(args, "echo", "[--text TEXT] [--format markdown|csv] [--out DIR]", opts);
  if (!vm) return 0;
  const mc::ReportOutline outline{
      "echo", {"echo.md", "echo.csv"}, {}, {mc::ReportFormat::kMarkdown, mc::ReportFormat::kCsv}};
  const StdoutChoice shown = read_stdout_choice(*vm, outline);
  std::optional<OutputFolderOption> out = prepare_report_folder(*vm, outline);
  if ((*vm)["fail"].as<bool>()) throw std::logic_error("echo failed");
  const std::string text = (*vm)["text"].as<std::string>();
  if (text.empty()) throw InputError("--text", "(empty)", "give something to print");
  mc::Report report(outline);
  report.file("echo.md", "# " + text + "\n")
      .file("echo.csv", "text\n" + text + "\n")
      .shown_file(mc::ReportFormat::kMarkdown, "echo.md")
      .shown_file(mc::ReportFormat::kCsv, "echo.csv")
      .summary({"echo: " + text + "\n", [](const std::optional<std::string>& folder) {
                  return mc::full_tables_line("echo", {"echo.md"}, folder);
                }});
  write_report(report, shown, out, *vm);
  return 0;
}

constexpr Subcommand kWithEcho[] = {{"echo", cmd_echo, "prints its text (a test-only subcommand)"}};

struct Outcome {
  int code;
  std::string out, err;
};

Outcome insmc(std::vector<std::string> args) {
  args.insert(args.begin(), "insmc");
  std::vector<const char*> argv;
  for (const std::string& a : args) argv.push_back(a.c_str());
  testing::internal::CaptureStdout();
  testing::internal::CaptureStderr();
  const int code = dispatch(kWithEcho, static_cast<int>(argv.size()), argv.data());
  std::fflush(stdout);
  std::fflush(stderr);
  Outcome o{code, testing::internal::GetCapturedStdout(), testing::internal::GetCapturedStderr()};
  return o;
}

std::string read(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::filesystem::path scratch_folder(const std::string& name) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("insmc_test_only_subcommand_" + name + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  return dir;
}

TEST(TestOnlySubcommand, PrintsItsReportInEachFormatItOffers) {
  EXPECT_EQ(insmc({"echo", "--text", "hi", "--full"}).out, "# hi\n");
  const Outcome csv = insmc({"echo", "--text", "hi", "--format", "csv"});
  EXPECT_EQ(csv.code, 0);
  EXPECT_EQ(csv.out, "text\nhi\n");
}

// The summary, --full, --quiet and --out together (docs/outputs.md, "Stdout
// beside the set"): the line naming the full tables follows the summary
// always, and the full markdown when --out is given.
TEST(TestOnlySubcommand, ItsSummaryAndTheLineUnderItFollowFullAndOut) {
  const std::string how = "Full tables (every axis and time): insmc echo --full, or --out DIR for echo.md, or --format csv\n";
  EXPECT_EQ(insmc({"echo", "--text", "hi"}).out, "echo: hi\n\n" + how);
  const std::filesystem::path dir = scratch_folder("summary");
  const std::string where = "Full tables (every axis and time): " + (dir / "echo.md").string() + "\n";
  EXPECT_EQ(insmc({"echo", "--text", "hi", "--out", dir.string()}).out, "echo: hi\n\n" + where);
  std::filesystem::remove_all(dir);
  EXPECT_EQ(insmc({"echo", "--text", "hi", "--full", "--out", dir.string()}).out, "# hi\n\n" + where);
  std::filesystem::remove_all(dir);
  const Outcome quiet = insmc({"echo", "--text", "hi", "--quiet", "--out", dir.string()});
  EXPECT_EQ(quiet.code, 0);
  EXPECT_EQ(quiet.out, "");
  EXPECT_EQ(read(dir / "echo.md"), "# hi\n");  // the set is still written
  std::filesystem::remove_all(dir);
  // csv and json print their file as it is, with or without a summary.
  EXPECT_EQ(insmc({"echo", "--text", "hi", "--format", "csv", "--full"}).out, "text\nhi\n");
}

TEST(TestOnlySubcommand, AFormatItsLayoutDoesNotOfferIsRefusedWithExitTwo) {
  const Outcome o = insmc({"echo", "--format", "json"});
  EXPECT_EQ(o.code, 2);
  EXPECT_EQ(o.err, "insmc echo: --format = json: echo prints markdown or csv\n");
  EXPECT_EQ(o.out, "");
}

TEST(TestOnlySubcommand, WritesItsSetWholeIntoOut) {
  const std::filesystem::path dir = scratch_folder("set");
  const Outcome o = insmc({"echo", "--text", "set", "--out", dir.string()});
  ASSERT_EQ(o.code, 0) << o.err;
  EXPECT_EQ(read(dir / "echo.md"), "# set\n");
  EXPECT_EQ(read(dir / "echo.csv"), "text\nset\n");
  EXPECT_NE(read(dir / ".insmc-set").find("command echo"), std::string::npos);
  std::filesystem::remove_all(dir);
}

TEST(TestOnlySubcommand, ItsFailuresAreOneLineAndAnExitCode) {
  const Outcome bad = insmc({"echo", "--text", ""});
  EXPECT_EQ(bad.code, 2);
  EXPECT_EQ(bad.err, "insmc echo: --text = (empty): give something to print\n");
  const Outcome unknown = insmc({"echo", "--colour", "red"});
  EXPECT_EQ(unknown.code, 2);
  EXPECT_NE(unknown.err.find("(see insmc echo --help)"), std::string::npos) << unknown.err;
  const Outcome defect = insmc({"echo", "--fail"});
  EXPECT_EQ(defect.code, 3);
  EXPECT_EQ(defect.err, "insmc echo: error: echo failed\n");
  const Outcome other = insmc({"ohce"});
  EXPECT_EQ(other.code, 2);
  EXPECT_NE(other.err.find("unknown subcommand 'ohce'"), std::string::npos);
}

TEST(TestOnlySubcommand, TheUsageAndItsHelpNameIt) {
  const Outcome usage = insmc({"--help"});
  EXPECT_EQ(usage.code, 0);
  EXPECT_NE(usage.out.find("  echo         prints its text (a test-only subcommand)"), std::string::npos) << usage.out;
  const Outcome help = insmc({"echo", "--help"});
  EXPECT_EQ(help.code, 0);
  EXPECT_NE(help.out.find("--text"), std::string::npos) << help.out;
}

}  // namespace
}  // namespace insmc::app
