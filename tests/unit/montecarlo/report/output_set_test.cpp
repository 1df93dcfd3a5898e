// Tests for montecarlo/report/output_set.h, output_file.h, output_lock.h,
// output_target.h and output_manifest.h: what is checked before the work,
// how a set goes in (new, swapped, in place beside foreign files), what is
// never replaced, the lock, and the clean-up of stale temporaries.
#include "montecarlo/report/output_set.h"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>

#include "montecarlo/report/atomic_file.h"
#include "montecarlo/report/output_error.h"
#include "montecarlo/report/output_file.h"
#include "montecarlo/report/output_lock.h"
#include "montecarlo/report/output_manifest.h"
#include "montecarlo/report/output_target.h"

namespace insmc::mc {
namespace {

namespace fs = std::filesystem;

std::string read_all(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

void write_plain(const fs::path& path, const std::string& text) { std::ofstream(path, std::ios::binary) << text; }

std::set<std::string> entries(const fs::path& dir) {
  std::set<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.insert(e.path().filename().string());
  return names;
}

const OutputSetFiles kFirst = {{"a.csv", "first a\n"}, {"b.md", "first b\n"}};
const OutputSetFiles kSecond = {{"a.csv", "second a\n"}, {"b.md", "second b\n"}};

class OutputSet : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() / ("insmc_output_set_test_" + std::to_string(::getpid()) + "_" + info->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

TEST_F(OutputSet, ManifestRoundTripsAndRejectsAnythingElse) {
  const OutputManifest m{"run", {"b.md", "a.csv"}};
  const auto parsed = parse_manifest(render_manifest(m));
  ASSERT_TRUE(parsed.has_value());
  EXPECT_EQ(parsed->command, "run");
  EXPECT_EQ(parsed->files, (std::vector<std::string>{"a.csv", "b.md"}));
  EXPECT_FALSE(parse_manifest("insmc output set 1\ncommand run\nfile a.csv"));  // no final newline
  EXPECT_FALSE(parse_manifest("insmc output set 1\ncommand run\nfile ../x\n"));
  EXPECT_FALSE(parse_manifest("insmc output set 1\ncommand run\nfile b\nfile a\n"));  // not sorted
  EXPECT_FALSE(parse_manifest("something else\n"));
}

TEST_F(OutputSet, ANewFolderAppearsWholeWithItsManifestAndNothingBeside) {
  OutputFolder out((dir_ / "o").string() + "/", "run");  // a trailing slash is fine
  EXPECT_FALSE(fs::exists(dir_ / "o")) << "the folder appears only with the finished set";
  EXPECT_EQ(out.write(kFirst), SetPlacement::kNew);
  EXPECT_EQ(entries(dir_ / "o"), (std::set<std::string>{"a.csv", "b.md", ".insmc-set"}));
  EXPECT_EQ(read_all(dir_ / "o" / "a.csv"), "first a\n");
  EXPECT_EQ(entries(dir_), (std::set<std::string>{"o", ".o.insmc-lock"})) << "lock held until destroyed";
}

TEST_F(OutputSet, LockFileGoesWithTheFolderObject) {
  { OutputFolder out((dir_ / "o").string(), "run"); }
  EXPECT_TRUE(fs::is_empty(dir_));
}

TEST_F(OutputSet, APreviousSetOfTheSameKindIsSwappedWhole) {
  OutputFolder((dir_ / "o").string(), "run").write(kFirst);
  struct stat before {};
  ASSERT_EQ(::stat((dir_ / "o").c_str(), &before), 0);
  EXPECT_EQ(OutputFolder((dir_ / "o").string(), "run").write(kSecond), SetPlacement::kExchanged);
  EXPECT_EQ(read_all(dir_ / "o" / "a.csv"), "second a\n");
  EXPECT_EQ(read_all(dir_ / "o" / "b.md"), "second b\n");
  struct stat after {};
  ASSERT_EQ(::stat((dir_ / "o").c_str(), &after), 0);
  EXPECT_NE(before.st_ino, after.st_ino) << "a new folder took the old one's place";
  EXPECT_EQ((after.st_mode & 07777), (before.st_mode & 07777)) << "the folder keeps its permissions";
  EXPECT_EQ(entries(dir_), (std::set<std::string>{"o"})) << "the old set and the lock are gone";
}

TEST_F(OutputSet, AnEmptyExistingFolderIsSwapped) {
  fs::create_directory(dir_ / "o");
  EXPECT_EQ(OutputFolder((dir_ / "o").string(), "run").write(kFirst), SetPlacement::kExchanged);
  EXPECT_EQ(read_all(dir_ / "o" / "b.md"), "first b\n");
}

TEST_F(OutputSet, ForeignFilesAreNeverMovedOrDeleted) {
  OutputFolder((dir_ / "o").string(), "run").write(kFirst);
  write_plain(dir_ / "o" / "notes.txt", "mine\n");
  fs::create_directory(dir_ / "o" / "sub");
  write_plain(dir_ / "o" / "sub" / "deep.txt", "mine too\n");
  struct stat before {};
  ASSERT_EQ(::stat((dir_ / "o").c_str(), &before), 0);
  EXPECT_EQ(OutputFolder((dir_ / "o").string(), "run").write(kSecond), SetPlacement::kInPlace);
  EXPECT_EQ(read_all(dir_ / "o" / "notes.txt"), "mine\n");
  EXPECT_EQ(read_all(dir_ / "o" / "sub" / "deep.txt"), "mine too\n");
  EXPECT_EQ(read_all(dir_ / "o" / "a.csv"), "second a\n");
  EXPECT_TRUE(parse_manifest(read_all(dir_ / "o" / ".insmc-set")).has_value());
  struct stat after {};
  ASSERT_EQ(::stat((dir_ / "o").c_str(), &after), 0);
  EXPECT_EQ(before.st_ino, after.st_ino) << "a folder with foreign files stays where it is";
  EXPECT_EQ(entries(dir_ / "o"), (std::set<std::string>{"a.csv", "b.md", ".insmc-set", "notes.txt", "sub"}));
}

TEST_F(OutputSet, AnotherKindOfSetIsKeptBesideTheNewOne) {
  OutputFolder((dir_ / "o").string(), "covariance").write({{"c.csv", "c\n"}});
  EXPECT_EQ(OutputFolder((dir_ / "o").string(), "run").write(kFirst), SetPlacement::kInPlace);
  EXPECT_EQ(read_all(dir_ / "o" / "c.csv"), "c\n");
  EXPECT_EQ(read_all(dir_ / "o" / "a.csv"), "first a\n");
}

TEST_F(OutputSet, TheWorkingDirectoryIsNeverSwapped) {
  fs::create_directory(dir_ / "o");
  const fs::path was = fs::current_path();
  fs::current_path(dir_ / "o");
  SetPlacement placement{};
  EXPECT_NO_THROW(placement = OutputFolder(".", "run").write(kFirst));
  fs::current_path(was);
  EXPECT_EQ(placement, SetPlacement::kInPlace);
  EXPECT_EQ(read_all(dir_ / "o" / "a.csv"), "first a\n");
}

TEST_F(OutputSet, NonRegularFilesAtASetNameAreRefusedAndLeftAlone) {
  fs::create_directory(dir_ / "o");
  ASSERT_EQ(::mkfifo((dir_ / "o" / "a.csv").c_str(), 0644), 0);
  EXPECT_THROW(OutputFolder((dir_ / "o").string(), "run", {"a.csv"}), OutputError) << "refused before the work";
  OutputFolder late((dir_ / "o").string(), "run");
  EXPECT_THROW(late.write(kFirst), OutputError) << "and when the names were not known before";
  EXPECT_TRUE(fs::is_fifo(dir_ / "o" / "a.csv"));
  EXPECT_EQ(entries(dir_ / "o"), (std::set<std::string>{"a.csv"}));

  fs::remove(dir_ / "o" / "a.csv");
  write_plain(dir_ / "victim", "keep\n");
  fs::create_symlink(dir_ / "victim", dir_ / "o" / "b.md");
  EXPECT_THROW(OutputFolder((dir_ / "o").string(), "run").write(kFirst), OutputError);
  EXPECT_TRUE(fs::is_symlink(dir_ / "o" / "b.md"));
  EXPECT_EQ(read_all(dir_ / "victim"), "keep\n");
}

TEST_F(OutputSet, PlantedTemporariesAreNeverWrittenThrough) {
  // A symbolic link with the old fixed temporary name and with the pattern
  // of the new names: neither is opened, the victim stays.
  write_plain(dir_ / "victim", "keep\n");
  fs::create_directory(dir_ / "o");
  fs::create_symlink(dir_ / "victim", dir_ / "o" / "a.csv.tmp");
  fs::create_symlink(dir_ / "victim", dir_ / "o" / ".a.csv.insmc-tmp-AAAAAA");
  OutputFolder((dir_ / "o").string(), "run").write(kFirst);
  EXPECT_EQ(read_all(dir_ / "victim"), "keep\n");
  EXPECT_EQ(read_all(dir_ / "o" / "a.csv"), "first a\n");
}

TEST_F(OutputSet, PathsThatCannotWorkAreRefusedBeforeTheWork) {
  write_plain(dir_ / "file", "x");
  EXPECT_THROW(OutputFolder((dir_ / "file").string(), "run"), OutputError) << "an existing file";
  EXPECT_THROW(OutputFolder((dir_ / "file" / "sub").string(), "run"), OutputError) << "a parent that is a file";
  EXPECT_THROW(OutputFolder("/dev/null", "run"), OutputError) << "a device";
  EXPECT_THROW(OutputFolder("", "run"), OutputError);
  EXPECT_THROW(OutputFolder("/", "run"), OutputError);
  fs::create_symlink(dir_ / "nowhere", dir_ / "dangling");
  EXPECT_THROW(OutputFolder((dir_ / "dangling").string(), "run"), OutputError);
  EXPECT_EQ(read_all(dir_ / "file"), "x");
  EXPECT_EQ(entries(dir_), (std::set<std::string>{"file", "dangling"}));
}

TEST_F(OutputSet, WithoutWritePermissionTheFolderIsRefusedBeforeTheWork) {
  if (::geteuid() == 0) GTEST_SKIP() << "root ignores permissions (tests/cli/output_test.cpp uses a path under a file)";
  fs::create_directories(dir_ / "ro" / "o");
  fs::permissions(dir_ / "ro" / "o", fs::perms::owner_read | fs::perms::owner_exec);
  EXPECT_THROW(OutputFolder((dir_ / "ro" / "o").string(), "run"), OutputError) << "the folder itself";
  fs::permissions(dir_ / "ro", fs::perms::owner_read | fs::perms::owner_exec);
  EXPECT_THROW(OutputFolder((dir_ / "ro" / "new").string(), "run"), OutputError) << "a folder that cannot be made";
  EXPECT_THROW(OutputFile((dir_ / "ro" / "runs.csv").string()), OutputError) << "a file that cannot be made";
  fs::permissions(dir_ / "ro", fs::perms::owner_all);
  fs::permissions(dir_ / "ro" / "o", fs::perms::owner_all);
}

TEST_F(OutputSet, AFolderWhoseParentIsNotWritableIsLockedItselfAndWrittenInPlace) {
  if (::geteuid() == 0) GTEST_SKIP() << "root ignores permissions";
  fs::create_directories(dir_ / "ro" / "o");
  fs::permissions(dir_ / "ro", fs::perms::owner_read | fs::perms::owner_exec);
  SetPlacement placement{};
  {
    OutputFolder first((dir_ / "ro" / "o").string(), "run");
    EXPECT_THROW(OutputFolder((dir_ / "ro" / "o").string(), "run"), OutputError) << "the folder's own lock";
    placement = first.write(kFirst);
  }
  fs::permissions(dir_ / "ro", fs::perms::owner_all);
  EXPECT_EQ(placement, SetPlacement::kInPlace);
  EXPECT_EQ(read_all(dir_ / "ro" / "o" / "a.csv"), "first a\n");
  EXPECT_EQ(entries(dir_ / "ro"), (std::set<std::string>{"o"}));
}

TEST_F(OutputSet, MissingParentsAreCreatedButNotTheFolder) {
  OutputFolder out((dir_ / "a" / "b" / "o").string(), "run");
  EXPECT_TRUE(fs::is_directory(dir_ / "a" / "b"));
  EXPECT_FALSE(fs::exists(dir_ / "a" / "b" / "o"));
  out.write(kFirst);
  EXPECT_EQ(read_all(dir_ / "a" / "b" / "o" / "a.csv"), "first a\n");
}

TEST_F(OutputSet, ASecondWriterIsRefusedWhileTheFirstHoldsTheLock) {
  OutputFolder first((dir_ / "o").string(), "run");
  try {
    OutputFolder second((dir_ / "o").string() + "/", "run");
    FAIL() << "the second writer was not refused";
  } catch (const OutputError& e) {
    EXPECT_NE(std::string(e.what()).find("another insmc"), std::string::npos) << e.what();
  }
  EXPECT_THROW(OutputFile((dir_ / "o").string()), OutputError) << "a file of that name shares the lock";
  first.write(kFirst);
  EXPECT_EQ(read_all(dir_ / "o" / "a.csv"), "first a\n");
}

TEST_F(OutputSet, ALeftOverLockFileDoesNotBlock) {
  write_plain(dir_ / ".o.insmc-lock", "");  // as a killed run leaves it (its flock died with it)
  OutputFolder((dir_ / "o").string(), "run").write(kFirst);
  EXPECT_EQ(entries(dir_), (std::set<std::string>{"o"}));
}

TEST_F(OutputSet, StaleTemporariesOfAKilledRunAreRemovedOthersAreNot) {
  fs::create_directory(dir_ / ".o.insmc-tmp-Ab12Cd");  // a killed run's set
  write_plain(dir_ / ".o.insmc-tmp-Ab12Cd" / "a.csv", "stale");
  write_plain(dir_ / ".other.insmc-tmp-Ab12Cd", "another target's");
  write_plain(dir_ / ".o.insmc-tmp-toolong1", "not the pattern");
  OutputFolder((dir_ / "o").string(), "run").write(kFirst);
  EXPECT_EQ(entries(dir_), (std::set<std::string>{"o", ".other.insmc-tmp-Ab12Cd", ".o.insmc-tmp-toolong1"}));
}

TEST(TemporaryNames, FollowTheirPatternOnly) {
  const std::string t = temporary_name("envelope.csv");
  EXPECT_TRUE(is_temporary_of(t, "envelope.csv")) << t;
  EXPECT_FALSE(is_temporary_of(t, "envelope"));
  EXPECT_FALSE(is_temporary_of(".envelope.csv.insmc-tmp-12345", "envelope.csv"));
  EXPECT_FALSE(is_temporary_of(".envelope.csv.insmc-tmp-12345/", "envelope.csv"));
  EXPECT_NE(temporary_name("x"), temporary_name("x"));
}

TEST_F(OutputSet, OutputFilesAreCheckedLockedAndReplacedAtomically) {
  EXPECT_THROW(OutputFile((dir_ / "runs.csv").string() + "/"), OutputError) << "a trailing slash names a folder";
  fs::create_directory(dir_ / "d");
  EXPECT_THROW(OutputFile((dir_ / "d").string()), OutputError) << "an existing folder";
  EXPECT_THROW(OutputFile((dir_ / "missing" / "runs.csv").string()), OutputError) << "no folder";
  EXPECT_THROW(OutputFile("/dev/null"), OutputError) << "a device";
  write_plain(dir_ / "victim", "keep\n");
  fs::create_symlink(dir_ / "victim", dir_ / "link.csv");
  EXPECT_THROW(OutputFile((dir_ / "link.csv").string()), OutputError) << "a symbolic link";
  EXPECT_EQ(read_all(dir_ / "victim"), "keep\n");
  write_plain(dir_ / ".runs.csv.insmc-tmp-zzzzzz", "a killed writer's");
  {
    OutputFile f((dir_ / "runs.csv").string());
    f.write("one\n");
    f.write("two\n");
    EXPECT_EQ(read_all(dir_ / "runs.csv"), "two\n");
  }
  EXPECT_EQ(entries(dir_), (std::set<std::string>{"d", "victim", "link.csv", "runs.csv"}));
}

}  // namespace
}  // namespace insmc::mc
