// A file of options is data, never a command line (apps/option_sources.h):
// run.json's settings.arguments, a checkpoint's arguments and a --config INI
// file give values of the study's options by name. A `--` separator, a bare
// word or a short option in them is refused with exit 2 in one line naming
// the file and the element, and nothing after it can name where insmc
// writes. Each case ends within 60 s under 1 GB (run_limited).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "montecarlo/study/run/checkpoint.h"
#include "tests/cli/run_program.h"

namespace insmc::testing {
namespace {

namespace fs = std::filesystem;

constexpr long kMaxRssKb = 1L << 20;  // 1 GB
constexpr int kMaxSeconds = 60;

std::string write(const TempDir& dir, const std::string& name, const std::string& text) {
  std::ofstream(dir.path() / name, std::ios::binary) << text;
  return (dir.path() / name).string();
}

/// Exit 2 in one line naming `names`, within the limits.
void expect_refused(const std::string& args, const std::string& names) {
  const ProgramResult r = run_limited(args, kMaxSeconds);
  EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << args << "\n" << r.err;
  EXPECT_NE(r.err.find(names), std::string::npos) << args << "\n" << r.err;
  EXPECT_LT(r.peak_rss_kb, kMaxRssKb) << args;
}

std::string json_array(const std::vector<std::string>& elements) {
  std::string out = "[";
  for (const std::string& e : elements) out += (out.size() > 1 ? ", \"" : "\"") + e + "\"";
  return out + "]";
}

TEST(FilesOfOptions, RunJsonArgumentsAreOptionsByNameNotACommandLine) {
  TempDir dir;
  const std::string elsewhere = dir.str() + "/elsewhere";
  const auto run_json = [&](const std::string& name, const std::vector<std::string>& arguments) {
    return write(dir, name, "{\"settings\": {\"arguments\": " + json_array(arguments) + "}}");
  };
  // After a `--` every option was once taken as typed: --out wrote there.
  const std::vector<std::string> smuggled_options = {
      "--out=" + elsewhere, "--checkpoint=" + elsewhere, "--config=" + elsewhere, "--replay=0", "--format=csv",
      "--threads=1",        "--from=" + elsewhere,       "--resume=" + elsewhere, "--help"};
  for (const std::string& smuggled : smuggled_options) {
    const std::string file = run_json("dashes.json", {"--samples=2048", "--", smuggled});
    expect_refused("run --quiet --from " + file, file + ": settings.arguments[1] = '--' is not an option by name");
  }
  // Nor a short option, an abbreviation, a bare word, an empty name, a value
  // for a switch or an option given twice.
  expect_refused("run --from " + run_json("short.json", {"-h"}), "settings.arguments[0] must be an option");
  expect_refused("run --from " + run_json("abbrev.json", {"--samp=2048"}), "settings.arguments[0] names an unknown option 'samp'");
  expect_refused("run --from " + run_json("word.json", {"--samples=2048", "--", "x"}), "settings.arguments[2] must be an option");
  expect_refused("run --from " + run_json("empty.json", {"--=5"}), "settings.arguments[0] = '--=5'");
  expect_refused("run --from " + run_json("twice.json", {"--samples=2048", "--samples=4096"}),
                 "settings.arguments[1] gives --samples twice (first in [0])");
  expect_refused("run --from " + run_json("value.json", {"--samples"}), "settings.arguments[0] gives --samples no value");
  EXPECT_FALSE(fs::exists(elsewhere));
  // What insmc itself writes is read back (the command line's options win).
  const ProgramResult first = run_limited("run --samples 2048 --quiet --out " + dir.str() + "/first", kMaxSeconds);
  ASSERT_EQ(first.exit_code, 0) << first.err;
  const ProgramResult again = run_limited(
      "run --from " + dir.str() + "/first/run.json --samples 2048 --format csv", kMaxSeconds);
  EXPECT_EQ(again.exit_code, 0) << again.err;
  EXPECT_EQ(again.out, read_file(dir.path() / "first" / "envelope.csv"));
}

TEST(FilesOfOptions, ACheckpointsArgumentsAreOptionsByName) {
  TempDir dir;
  const std::string ck = dir.str() + "/study.ck";
  const ProgramResult made = run_limited("run --samples 2048 --quiet --checkpoint " + ck, kMaxSeconds);
  ASSERT_EQ(made.exit_code, 0) << made.err;
  mc::Checkpoint checkpoint = mc::decode_checkpoint(read_file(ck), ck);
  // The same study (the fingerprint holds), with a `--` and an output after it.
  const std::string elsewhere = dir.str() + "/elsewhere";
  checkpoint.args.push_back("--");
  checkpoint.args.push_back("--out=" + elsewhere);
  const std::string planted = write(dir, "planted.ck", mc::encode_checkpoint(checkpoint));
  expect_refused("run --quiet --resume " + planted,
                 fmt::format("--resume = {}: the checkpoint's arguments[{}] = '--' is not an option by name", planted,
                             checkpoint.args.size() - 2));
  EXPECT_FALSE(fs::exists(elsewhere));
  checkpoint.args.pop_back();
  checkpoint.args.back() = "--out=" + elsewhere;
  const std::string named = write(dir, "named.ck", mc::encode_checkpoint(checkpoint));
  expect_refused("run --quiet --resume " + named, "holds --out, which names where insmc writes");
  EXPECT_FALSE(fs::exists(elsewhere));
}

TEST(FilesOfOptions, AnIniKeyIsALongNameAlone) {
  TempDir dir;
  expect_refused("run --config " + write(dir, "dashes.ini", "samples = 2048\n-- = --out=x\n"),
                 "dashes.ini:2: unknown option '--'");
  expect_refused("run --config " + write(dir, "short.ini", "-h = 1\n"), "short.ini:1: unknown option '-h'");
  expect_refused("run --config " + write(dir, "abbrev.ini", "samp = 2048\n"), "abbrev.ini:1: unknown option 'samp'");
  expect_refused("run --config " + write(dir, "out.ini", "samples = 2048\nout = x\n"), "out.ini:2: out: names where");
}

}  // namespace
}  // namespace insmc::testing
