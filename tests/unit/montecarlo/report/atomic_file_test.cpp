// Tests for montecarlo/report/atomic_file.h.
#include "montecarlo/report/atomic_file.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

namespace insmc::mc {
namespace {

namespace fs = std::filesystem;

std::string read_all(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// A fresh directory per test, removed afterwards.
class AtomicFile : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() /
           ("insmc_atomic_file_test_" + std::to_string(::getpid()) + "_" + info->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  bool only_entry_is(const fs::path& expected) const {
    int entries = 0;
    bool found = false;
    for (const auto& e : fs::directory_iterator(dir_)) {
      ++entries;
      found = found || e.path() == expected;
    }
    return entries == 1 && found;
  }

  fs::path dir_;
};

TEST_F(AtomicFile, WritesContentsAndLeavesNoTemporary) {
  const fs::path path = dir_ / "table.csv";
  const std::string contents = "a,b\n1,2\n";
  write_file_atomically(path, contents);
  EXPECT_EQ(read_all(path), contents);
  EXPECT_FALSE(fs::exists(dir_ / "table.csv.tmp"));
  EXPECT_TRUE(only_entry_is(path));
}

TEST_F(AtomicFile, OverwritesAnExistingFile) {
  const fs::path path = dir_ / "out.md";
  write_file_atomically(path, "first version, longer than the second\n");
  write_file_atomically(path, "second\n");
  EXPECT_EQ(read_all(path), "second\n");
  EXPECT_TRUE(only_entry_is(path));
}

TEST_F(AtomicFile, BinaryAndEmptyContents) {
  const fs::path path = dir_ / "blob.bin";
  const std::string binary("\0\x01\xff\n\r\0end", 9);
  write_file_atomically(path, binary);
  EXPECT_EQ(read_all(path), binary);
  write_file_atomically(path, "");
  EXPECT_TRUE(fs::exists(path));
  EXPECT_EQ(fs::file_size(path), 0u);
}

TEST_F(AtomicFile, MissingDirectoryThrowsWithPathAndLeavesNothing) {
  // Tests may run as root, where permission bits do not stop writes, so the
  // unwritable directory is one that does not exist.
  const fs::path path = dir_ / "no_such_dir" / "out.csv";
  try {
    write_file_atomically(path, "x");
    FAIL() << "expected std::runtime_error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(path.string()), std::string::npos) << e.what();
  }
  EXPECT_FALSE(fs::exists(dir_ / "no_such_dir"));
  EXPECT_TRUE(fs::is_empty(dir_));
}

TEST_F(AtomicFile, ReadOnlyDirectoryThrowsAndLeavesNothing) {
  if (::geteuid() == 0) GTEST_SKIP() << "root ignores directory permissions";
  const fs::path ro = dir_ / "ro";
  fs::create_directory(ro);
  fs::permissions(ro, fs::perms::owner_read | fs::perms::owner_exec);
  EXPECT_THROW(write_file_atomically(ro / "out.csv", "x"), std::runtime_error);
  fs::permissions(ro, fs::perms::owner_all);
  EXPECT_TRUE(fs::is_empty(ro));
}

TEST_F(AtomicFile, FailedRenameRemovesTemporaryAndKeepsTarget) {
  // The target is a non-empty directory: the temporary is written, then
  // rename(2) fails (EISDIR); the temporary must be removed.
  const fs::path path = dir_ / "target";
  fs::create_directories(path / "child");
  EXPECT_THROW(write_file_atomically(path, "x"), std::runtime_error);
  EXPECT_FALSE(fs::exists(dir_ / "target.tmp"));
  EXPECT_TRUE(fs::is_directory(path / "child"));
}

}  // namespace
}  // namespace insmc::mc
