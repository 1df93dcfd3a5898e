// End-to-end tests of `insmc run --checkpoint` and `--resume`: the file is
// written and kept; resuming a finished checkpoint reproduces the files; a
// run interrupted by SIGTERM says so in one line, exits 143 and resumes to
// the same bytes as an uninterrupted run; a bad checkpoint is refused with
// exit 2.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <fstream>
#include <thread>

#include "tests/cli/checkpoint_helpers.h"
#include "tests/cli/run_program.h"

namespace insmc::testing {
namespace {

// Cheap settings (scheme none, a coarse grid) so that Debug + sanitizer
// builds stay fast; the samples are chosen per test.
const std::string kStudy = " --scheme none --system 2 --grid-step 30min --seed 11";

TEST(Checkpoint, IsWrittenAtTheEndKeptAndResumesToTheSameFiles) {
  TempDir dir;
  const std::string study = " --samples 5000" + kStudy;
  const std::string ck = dir.str() + "/run.ck";
  const auto plain = run_insmc("run" + study + " --out " + dir.str() + "/plain --format csv");
  ASSERT_EQ(plain.exit_code, 0) << plain.err;
  const auto with_ck = run_insmc("run" + study + " --checkpoint " + ck + " --out " + dir.str() + "/ck");
  ASSERT_EQ(with_ck.exit_code, 0) << with_ck.err;
  EXPECT_EQ(with_ck.err, "");
  ASSERT_TRUE(std::filesystem::exists(ck));
  EXPECT_FALSE(std::filesystem::exists(ck + ".tmp"));
  expect_same_envelopes(dir.path() / "plain", dir.path() / "ck");
  EXPECT_NE(read_file(dir.path() / "ck" / "run.json").find("\"resumed_from_sample\": 0,"), std::string::npos);

  // --resume needs no other option: the settings come back; where to write
  // does not (a checkpoint, like any file of options, names no output).
  const auto resumed = run_insmc("run --resume " + ck + " --format csv");
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  EXPECT_EQ(resumed.out, plain.out);
  EXPECT_EQ(read_file(ck).find("--out"), std::string::npos) << "the checkpoint keeps no output path";
  const auto elsewhere = run_insmc("run --resume " + ck + " --out " + dir.str() + "/again --threads 1");
  ASSERT_EQ(elsewhere.exit_code, 0) << elsewhere.err;
  expect_same_envelopes(dir.path() / "plain", dir.path() / "again");
  EXPECT_NE(read_file(dir.path() / "again" / "run.json").find("\"resumed_from_sample\": 5000,"), std::string::npos);
  EXPECT_TRUE(std::filesystem::exists(ck));
}

TEST(Checkpoint, SigtermWritesTheCheckpointAndTheResumeGivesTheSameBytes) {
  TempDir dir;
  const std::uint64_t samples = samples_for_seconds(kStudy, 2.5);
  const std::string study = fmt_samples(samples) + kStudy;
  const std::string ck = dir.str() + "/run.ck";
  BackgroundProgram run(insmc_path() + " run" + study + " --checkpoint " + ck +
                        " --checkpoint-every 0.1s --out " + dir.str() + "/killed");
  wait_for_a_periodic_checkpoint(ck);
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  run.send(SIGTERM);
  const ProgramResult killed = run.wait();
  EXPECT_EQ(killed.exit_code, 128 + SIGTERM) << killed.err;
  EXPECT_EQ(std::count(killed.err.begin(), killed.err.end(), '\n'), 1) << killed.err;
  EXPECT_NE(killed.err.find("interrupted by SIGTERM: checkpoint " + ck + " written"), std::string::npos) << killed.err;
  EXPECT_NE(killed.err.find("continue with: insmc run --resume " + ck + " --out " + dir.str() + "/killed"),
            std::string::npos) << killed.err;
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "killed")) << "no output before the study is finished";
  ASSERT_TRUE(std::filesystem::exists(ck));

  const auto resumed = run_insmc("run --resume " + ck + " --out " + dir.str() + "/killed");
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  const std::uint64_t from = resumed_from_sample(dir.path() / "killed" / "run.json");
  EXPECT_GT(from, 0u);
  EXPECT_LT(from, samples) << "the run was interrupted before its end";
  const auto uninterrupted = run_insmc("run" + study + " --out " + dir.str() + "/whole");
  ASSERT_EQ(uninterrupted.exit_code, 0) << uninterrupted.err;
  expect_same_envelopes(dir.path() / "whole", dir.path() / "killed");
}

TEST(Checkpoint, BadCheckpointsAndOptionsAreRefusedWithExitTwo) {
  TempDir dir;
  const std::string ck = dir.str() + "/good.ck";
  ASSERT_EQ(run_insmc("run --samples 3000" + kStudy + " --checkpoint " + ck).exit_code, 0);
  const std::string good = read_file(ck);
  const auto write = [&](const std::string& name, const std::string& bytes) {
    std::ofstream(dir.path() / name, std::ios::binary) << bytes;
    return (dir.path() / name).string();
  };
  std::string flipped = good;
  flipped[flipped.size() / 2] ^= 1;
  std::string other_version = good;
  const std::string version = run_insmc("--version").out.substr(6);  // "insmc X.Y.Z\n"
  const std::size_t at = other_version.find(version.substr(0, version.size() - 1));
  ASSERT_NE(at, std::string::npos);
  other_version[at] = other_version[at] == '9' ? '8' : '9';
  struct Case {
    std::string args, names;
  };
  const std::vector<Case> cases{
      {"run --resume " + dir.str() + "/missing.ck", "cannot open"},
      {"run --resume " + write("text.ck", "samples = 5\n"), "not an insmc checkpoint"},
      {"run --resume " + write("short.ck", good.substr(0, good.size() / 3)), "corrupt"},
      {"run --resume " + write("flipped.ck", flipped), "corrupt"},
      {"run --resume " + write("version.ck", other_version), "written by insmc"},
      {"run --resume " + ck + " --samples 100", "--samples"},
      {"run --samples 3000" + kStudy + " --checkpoint " + dir.str() + "/no/such/dir/x.ck", "--checkpoint"},
      {"run --samples 3000 --checkpoint " + dir.str() + "/x.ck --checkpoint-every 0s", "--checkpoint-every"},
      {"run --samples 3000 --checkpoint " + dir.str() + "/x.ck --test-duration 10min,15min", "sweep"},
  };
  for (const Case& c : cases) {
    const auto r = run_insmc(c.args + " --out " + dir.str() + "/out");
    EXPECT_EQ(r.exit_code, 2) << c.args << "\n" << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << c.args << "\n" << r.err;
    EXPECT_NE(r.err.find(c.names), std::string::npos) << c.args << "\n" << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir.path() / "out")) << c.args;
  }
  EXPECT_EQ(read_file(ck), good) << "a refused resume leaves the checkpoint alone";
}

}  // namespace
}  // namespace insmc::testing
