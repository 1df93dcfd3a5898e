// End-to-end tests of the output paths (docs/outputs.md): bad paths exit 2
// before any work, planted links and non-regular files are never written
// through or replaced, a SIGKILL at any moment leaves one whole set, and
// two runs on one --out: one wins whole, the other exits 2.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <chrono>
#include <limits>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <random>
#include <set>
#include <string>
#include <thread>

#include "tests/cli/checkpoint_helpers.h"
#include "tests/cli/run_program.h"

namespace insmc::testing {
namespace {

namespace fs = std::filesystem;

const std::vector<std::string> kRunFiles = {"envelope.csv", "envelope_grid.csv", "envelope.md", "envelope.gp", "envelope.svg", "envelope.png",
                                            "run.json"};

std::set<std::string> entries(const fs::path& dir) {
  std::set<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.insert(e.path().filename().string());
  return names;
}

/// run.json without its one line that differs between two runs of one study.
std::string run_json_without_elapsed(const fs::path& file) {
  std::istringstream in(read_file(file));
  std::string out, line;
  while (std::getline(in, line))
    if (line.find("\"elapsed_s\"") == std::string::npos) out += line + "\n";
  return out;
}

/// Whether `dir` holds exactly the set in `reference` (and its manifest).
bool holds_the_set_of(const fs::path& dir, const fs::path& reference) {
  std::set<std::string> wanted(kRunFiles.begin(), kRunFiles.end());
  wanted.insert(".insmc-set");
  if (entries(dir) != wanted) return false;
  for (const std::string& f : kRunFiles) {
    if (f == "run.json") {
      if (run_json_without_elapsed(dir / f) != run_json_without_elapsed(reference / f)) return false;
    } else if (read_file(dir / f) != read_file(reference / f)) {
      return false;
    }
  }
  return read_file(dir / ".insmc-set") == read_file(reference / ".insmc-set");
}

int line_count(const std::string& s) { return static_cast<int>(std::count(s.begin(), s.end(), '\n')); }

/// A refusal: exit 2, one line naming the option and the path.
void expect_refused(const ProgramResult& r, const std::string& option, const std::string& path,
                    const std::string& args) {
  EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.err;
  EXPECT_EQ(line_count(r.err), 1) << args << "\n" << r.err;
  EXPECT_NE(r.err.find(option + " = " + path), std::string::npos) << args << "\n" << r.err;
  EXPECT_TRUE(r.out.empty()) << args << ": printed before refusing\n" << r.out;
}

TEST(Outputs, APlantedSymlinkAtTheOldTemporaryNameIsNotWrittenThrough) {
  TempDir dir;
  fs::create_directory(dir.path() / "o");
  std::ofstream(dir.path() / "victim") << "keep\n";
  for (const std::string& f : kRunFiles) fs::create_symlink("../victim", dir.path() / "o" / (f + ".tmp"));
  const auto r = run_insmc("run --samples 2000 --out " + dir.str() + "/o --format csv");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(read_file(dir.path() / "victim"), "keep\n") << "a file outside --out was overwritten";
  EXPECT_EQ(read_file(dir.path() / "o" / "envelope.csv"), r.out);
  for (const std::string& f : kRunFiles) EXPECT_TRUE(fs::is_symlink(dir.path() / "o" / (f + ".tmp"))) << f;
}

TEST(Outputs, DevicesAndFifosAreRefusedBeforeTheWorkAndLeftAlone) {
  TempDir dir;
  const std::string fifo = dir.str() + "/fifo";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0644), 0);
  fs::create_directory(dir.path() / "o");
  ASSERT_EQ(::mkfifo((dir.path() / "o" / "run.json").c_str(), 0644), 0);
  const std::string ck = dir.str() + "/x.ck";  // written before the work starts: proof that none started
  const std::string big = "run --samples 100000000 --checkpoint " + ck + " --out ";
  for (const std::string& out : {std::string("/dev/null"), fifo, dir.str() + "/o"}) {
    const std::string args = big + out;
    expect_refused(run_insmc(args), "--out", out, args);
    EXPECT_FALSE(fs::exists(ck)) << args << ": the work had started";
  }
  EXPECT_TRUE(fs::is_character_file("/dev/null"));
  EXPECT_TRUE(fs::is_fifo(fifo));
  EXPECT_TRUE(fs::is_fifo(dir.path() / "o" / "run.json"));
  EXPECT_EQ(entries(dir.path() / "o"), (std::set<std::string>{"run.json"}));
  const std::string args = "run --samples 100000000 --checkpoint " + fifo;
  expect_refused(run_insmc(args), "--checkpoint", fifo, args);
  EXPECT_TRUE(fs::is_fifo(fifo));
  const std::string sim = "simulate --runs 200 --out /dev/null";
  expect_refused(run_insmc(sim), "--out", "/dev/null", sim);
}

TEST(Outputs, PathsThatCannotBeWrittenExitTwoBeforeTheWork) {
  TempDir dir;
  std::ofstream(dir.path() / "file") << "x";
  fs::create_directory(dir.path() / "existing_dir");
  const std::string ck = dir.str() + "/x.ck";
  struct Case {
    std::string args, option, path;
  };
  const std::string under_file = dir.str() + "/file/sub";  // as unwritable as it gets for root
  const std::vector<Case> cases = {
      {"run --samples 100000000 --checkpoint " + ck + " --out " + under_file, "--out", under_file},
      {"run --samples 100000000 --checkpoint " + ck + " --out " + dir.str() + "/file", "--out", dir.str() + "/file"},
      {"covariance --out " + under_file, "--out", under_file},
      {"tables --out " + under_file, "--out", under_file},
      {"gap-validate --out " + under_file, "--out", under_file},
      {"simulate --runs 200 --out " + dir.str() + "/existing_dir", "--out", dir.str() + "/existing_dir"},
      {"simulate --runs 200 --out " + dir.str() + "/new.csv/", "--out", dir.str() + "/new.csv/"},
      {"simulate --runs 200 --out " + under_file + "/runs.csv", "--out", under_file + "/runs.csv"},
      {"run --samples 100000000 --checkpoint " + dir.str() + "/existing_dir", "--checkpoint",
       dir.str() + "/existing_dir"},
      {"run --samples 100000000 --checkpoint " + under_file + "/x.ck", "--checkpoint", under_file + "/x.ck"},
  };
  for (const Case& c : cases) {
    expect_refused(run_insmc(c.args), c.option, c.path, c.args);
    EXPECT_FALSE(fs::exists(ck)) << c.args << ": the work had started";
  }
  EXPECT_EQ(entries(dir.path()), (std::set<std::string>{"file", "existing_dir"})) << "nothing left behind";
  EXPECT_TRUE(fs::is_empty(dir.path() / "existing_dir"));
}

// A folder on a file system nothing can be created in: the message is of
// the output the user named, not of the lock file beside it.
TEST(Outputs, AnOutputInProcSaysTheFolderCannotBeCreated) {
  const ProgramResult r = run_insmc("run --samples 100 --out /proc/x");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_TRUE(has(r.err, "--out = /proc/x")) << r.err;
  EXPECT_TRUE(has(r.err, "cannot create the output in /proc")) << r.err;
  EXPECT_TRUE(has(r.err, "choose a folder you can write to")) << r.err;
  EXPECT_FALSE(has(r.err, ".lock")) << r.err;
}

TEST(Outputs, AResumeWithABadOutIsRefusedBeforeTheCheckpointIsTouched) {
  TempDir dir;
  const std::string ck = dir.str() + "/x.ck";
  ASSERT_EQ(run_insmc("run --samples 2000 --checkpoint " + ck).exit_code, 0);
  struct stat before {};
  ASSERT_EQ(::stat(ck.c_str(), &before), 0);
  std::ofstream(dir.path() / "file") << "x";
  const std::string out = dir.str() + "/file/sub";
  const std::string args = "run --resume " + ck + " --out " + out;
  expect_refused(run_insmc(args), "--out", out, args);
  struct stat after {};
  ASSERT_EQ(::stat(ck.c_str(), &after), 0);
  EXPECT_EQ(before.st_ino, after.st_ino) << "the checkpoint was rewritten: the resume had started";
}

TEST(Outputs, TrailingSlashesAndNewParentsWork) {
  TempDir dir;
  const auto r = run_insmc("run --samples 2000 --out " + dir.str() + "/newdir/ --format csv");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(read_file(dir.path() / "newdir" / "envelope.csv"), r.out);
  const auto c = run_insmc("covariance --out " + dir.str() + "/a/b/c//");
  ASSERT_EQ(c.exit_code, 0) << c.err;
  EXPECT_TRUE(fs::exists(dir.path() / "a" / "b" / "c" / "covariance.csv"));
  EXPECT_EQ(entries(dir.path()), (std::set<std::string>{"newdir", "a"})) << "no lock or temporary left";
}

TEST(Outputs, TheUsersOwnFilesInTheFolderAreKept) {
  TempDir dir;
  const fs::path o = dir.path() / "o";
  fs::create_directories(o / "mine");
  std::ofstream(o / "notes.txt") << "mine\n";
  std::ofstream(o / "mine" / "deep.txt") << "deep\n";
  ASSERT_EQ(run_insmc("run --samples 2000 --out " + o.string()).exit_code, 0);
  ASSERT_EQ(run_insmc("run --samples 2000 --seed 2 --out " + o.string()).exit_code, 0);
  ASSERT_EQ(run_insmc("covariance --out " + o.string()).exit_code, 0);
  EXPECT_EQ(read_file(o / "notes.txt"), "mine\n");
  EXPECT_EQ(read_file(o / "mine" / "deep.txt"), "deep\n");
  EXPECT_TRUE(fs::exists(o / "envelope.csv"));
  EXPECT_TRUE(fs::exists(o / "covariance.csv"));
  EXPECT_NE(read_file(o / "run.json").find("\"seed\": 2"), std::string::npos);
}

TEST(Outputs, ASigkillAtAnyMomentLeavesOneWholeSet) {
  TempDir dir;
  const std::string study = " --samples 3000";
  // The two complete sets, written once each without interruption; the
  // shortest of the three uninterrupted runs times the kills (on a loaded
  // machine one run can take several times another).
  double whole_s = std::numeric_limits<double>::infinity();
  const auto timed = [&whole_s](const std::string& args) {
    const auto start = std::chrono::steady_clock::now();
    const auto r = run_insmc(args);
    whole_s = std::min(whole_s, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    return r;
  };
  for (const char* seed : {"1", "2"}) {
    const auto r = timed("run" + study + " --seed " + seed + " --out " + dir.str() + "/ref" + seed);
    ASSERT_EQ(r.exit_code, 0) << r.err;
  }
  const fs::path o = dir.path() / "o";
  ASSERT_EQ(timed("run" + study + " --seed 1 --out " + o.string()).exit_code, 0);
  ASSERT_TRUE(holds_the_set_of(o, dir.path() / "ref1"));

  // Kills spread over the whole run and most of them near its end, where the
  // set is written; each run writes the other seed's set over what is there.
  std::mt19937 random(12345);
  std::uniform_real_distribution<double> anywhere(0.3, 1.1), near_the_end(0.9, 1.03);
  int killed = 0, finished = 0, in_write_phase = 0;
  for (int i = 0; i < 16; ++i) {
    const std::string seed = i % 2 == 0 ? "2" : "1";
    BackgroundProgram run(insmc_path() + " run" + study + " --seed " + seed + " --out " + o.string());
    std::this_thread::sleep_for(std::chrono::duration<double>((i % 4 == 0 ? anywhere : near_the_end)(random) * whole_s));
    run.send(SIGKILL);
    const ProgramResult r = run.wait();
    (r.exit_code == 128 + SIGKILL ? killed : finished) += 1;
    for (const std::string& e : entries(dir.path())) in_write_phase += e.rfind(".o.insmc-tmp-", 0) == 0 ? 1 : 0;
    const bool old_set = holds_the_set_of(o, dir.path() / "ref1"), new_set = holds_the_set_of(o, dir.path() / "ref2");
    ASSERT_TRUE(old_set || new_set) << "kill " << i << ": the folder holds " << ::testing::PrintToString(entries(o));
  }
  std::cout << "[ kills ] " << killed << " killed (" << in_write_phase
            << " while a temporary set existed), " << finished << " finished before the kill\n";
  EXPECT_GT(killed, 0);
  // A killed run's temporaries are recognisable and the next run clears them.
  ASSERT_EQ(run_insmc("run" + study + " --seed 2 --out " + o.string()).exit_code, 0);
  EXPECT_TRUE(holds_the_set_of(o, dir.path() / "ref2"));
  EXPECT_EQ(entries(dir.path()), (std::set<std::string>{"ref1", "ref2", "o"}));
}

TEST(Outputs, OfTwoRunsOnOneFolderOneWinsWholeAndTheOtherExitsTwo) {
  TempDir dir;
  const std::string study = fmt_samples(samples_for_seconds("", 1.5));
  const fs::path o = dir.path() / "o";
  BackgroundProgram first(insmc_path() + " run" + study + " --seed 1 --out " + o.string());
  BackgroundProgram second(insmc_path() + " run" + study + " --seed 2 --out " + o.string() + "/");
  const ProgramResult a = first.wait(), b = second.wait();
  const bool first_won = a.exit_code == 0;
  const ProgramResult& winner = first_won ? a : b;
  const ProgramResult& loser = first_won ? b : a;
  ASSERT_EQ(winner.exit_code, 0) << winner.err;
  EXPECT_EQ(loser.exit_code, 2) << loser.err;
  EXPECT_EQ(line_count(loser.err), 1) << loser.err;
  EXPECT_NE(loser.err.find("another insmc is writing"), std::string::npos) << loser.err;
  EXPECT_NE(loser.err.find("--out = "), std::string::npos) << loser.err;
  EXPECT_TRUE(loser.out.empty()) << "the refused run did no work";
  const auto ref = run_insmc("run" + study + " --seed " + (first_won ? "1" : "2") + " --out " + dir.str() + "/ref");
  ASSERT_EQ(ref.exit_code, 0) << ref.err;
  EXPECT_TRUE(holds_the_set_of(o, dir.path() / "ref")) << "the winner's set is whole";
  EXPECT_EQ(entries(dir.path()), (std::set<std::string>{"o", "ref"}));
}

}  // namespace
}  // namespace insmc::testing
