#include "lib/common/input_text.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "lib/common/input_error.h"

namespace insmc {
namespace {

namespace fs = std::filesystem;

TEST(EchoInput, KeepsPrintableTextAndValidUtf8) {
  EXPECT_EQ(echo_input("15min"), "15min");
  EXPECT_EQ(echo_input("45°"), "45°");  // valid UTF-8 is shown as is
}

TEST(EchoInput, EscapesControlBytesAndInvalidUtf8) {
  EXPECT_EQ(echo_input(std::string("a\nb\tc\rd")), "a\\nb\\tc\\rd");
  EXPECT_EQ(echo_input(std::string("x\x1b[31my", 7)), "x\\x1B[31my");
  EXPECT_EQ(echo_input(std::string("\0z", 2)), "\\x00z");
  EXPECT_EQ(echo_input("\x7f"), "\\x7F");
  EXPECT_EQ(echo_input("\xff\xfe"), "\\xFF\\xFE");
  EXPECT_EQ(echo_input("\xc3"), "\\xC3");          // truncated sequence
  EXPECT_EQ(echo_input("\xed\xa0\x80"), "\\xED\\xA0\\x80");  // a surrogate is not UTF-8
}

TEST(EchoInput, CutsAHugeValueAndGivesItsSize) {
  const std::string huge(1'000'000, 'a');
  const std::string shown = echo_input(huge);
  EXPECT_EQ(shown, std::string(kEchoMaxBytes, 'a') + "\u2026(1000000 bytes)");
  EXPECT_EQ(echo_input(std::string(kEchoMaxBytes, 'b')), std::string(kEchoMaxBytes, 'b'));  // exactly the cap: whole
  // Never cuts inside a character.
  const std::string degrees = std::string(kEchoMaxBytes - 1, 'c') + "°";
  EXPECT_EQ(echo_input(degrees), std::string(kEchoMaxBytes - 1, 'c') + "\u2026(41 bytes)");
}

TEST(OneLineValue, EscapesLineBreaksAndBlanksAtTheEnds) {
  EXPECT_EQ(one_line_value("a b"), "a b");
  EXPECT_EQ(one_line_value("in\nput.csv"), "in\\nput.csv");
  EXPECT_EQ(one_line_value(" x  "), "\\x20x\\x20\\x20");
  EXPECT_EQ(one_line_value("   "), "\\x20\\x20\\x20");
}

class ReadFileCapped : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("insmc_read_capped_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path write(const std::string& name, const std::string& text) {
    std::ofstream(dir_ / name, std::ios::binary) << text;
    return dir_ / name;
  }
  fs::path dir_;
};

std::string message_of(const fs::path& p, std::uint64_t cap) {
  try {
    read_file_capped(p, cap, "test file");
  } catch (const FileReadError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST_F(ReadFileCapped, ReadsUpToTheCapAndRefusesMore) {
  EXPECT_EQ(read_file_capped(write("ten", "0123456789"), 10, "test file"), "0123456789");
  const std::string m = message_of(write("eleven", "0123456789x"), 10);
  EXPECT_NE(m.find("larger than 10 bytes, the most a test file may hold"), std::string::npos) << m;
  EXPECT_EQ(read_file_capped(write("empty", ""), 10, "test file"), "");
}

TEST_F(ReadFileCapped, StopsReadingAnEndlessFile) {
  const std::string m = message_of("/dev/zero", 1 << 20);
  EXPECT_NE(m.find("/dev/zero: cannot read the test file: larger than 1 MiB"), std::string::npos) << m;
}

TEST_F(ReadFileCapped, ADirectoryOrAMissingFileIsAnError) {
  EXPECT_NE(message_of(dir_, 100).find("it is a directory"), std::string::npos);
  EXPECT_NE(message_of(dir_ / "missing", 100).find("missing: cannot open the test file: No such file"), std::string::npos);
  try {
    read_file_capped(dir_, 100, "test file");
    FAIL();
  } catch (const FileReadError& e) {
    EXPECT_EQ(e.why(), "cannot read the test file: it is a directory");
  }
}

TEST_F(ReadFileCapped, EscapesTheFileName) {
  const std::string m = message_of(dir_ / "a\nb", 100);
  EXPECT_EQ(m.find('\n'), std::string::npos) << m;
  EXPECT_NE(m.find("a\\nb"), std::string::npos) << m;
}

TEST(FormatBytes, NamesTheUnit) {
  EXPECT_EQ(format_bytes(1 << 20), "1 MiB");
  EXPECT_EQ(format_bytes(std::uint64_t{2} << 30), "2 GiB");
  EXPECT_EQ(format_bytes(16 * 1024), "16 KiB");
  EXPECT_EQ(format_bytes(1000), "1000 bytes");
}

}  // namespace
}  // namespace insmc
