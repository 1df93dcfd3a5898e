// The --config INI reader (montecarlo/study/run/config_file.h): entries with
// their sections and lines, file:line in every message, the line cap, and
// the first mistake told whether the text or the taker refuses it.
#include "montecarlo/study/run/config_file.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "lib/common/input_error.h"
#include "tests/unit/input_error_of.h"

namespace insmc::mc {
namespace {

std::vector<ConfigEntry> entries_of(const std::string& text) {
  std::vector<ConfigEntry> out;
  read_config_text(text, "study.ini", [&](const ConfigEntry& e) {
    out.push_back(e);
    return std::string();
  });
  return out;
}

std::string error_of(const std::string& text) {
  return test::input_error_of([&] {
    read_config_text(text, "study.ini", [](const ConfigEntry& e) {
      return e.key == "refused" ? std::string("refused by the taker") : std::string();
    });
  });
}

TEST(ConfigFile, ReadsKeysSectionsCommentsAndABom) {
  const auto e = entries_of("\xEF\xBB\xBF# study\nsamples = 1000\r\n\nbound = a=1 # first\n[study]\nseed=7");
  ASSERT_EQ(e.size(), 3u);
  EXPECT_EQ(e[0].key, "samples");
  EXPECT_EQ(e[0].value, "1000");
  EXPECT_EQ(e[0].line, 2u);
  EXPECT_EQ(e[1].key, "bound");
  EXPECT_EQ(e[1].value, "a=1");
  EXPECT_EQ(e[1].line, 4u);
  EXPECT_EQ(e[2].key, "study.seed");
  EXPECT_EQ(e[2].value, "7");
  EXPECT_EQ(e[2].line, 6u);
}

TEST(ConfigFile, MessagesNameFileAndLine) {
  EXPECT_EQ(error_of("just words\n"), "study.ini:1: 'just words' is not 'key = value' (e.g. samples = 100000)");
  EXPECT_EQ(error_of("\n = 5\n"), "study.ini:2: empty key before '=' in '= 5'");
  EXPECT_EQ(error_of("[study\n"), "study.ini:1: section line '[study' is not '[name]'");
  EXPECT_EQ(error_of("a = 1\nrefused = 2\n"), "study.ini:2: refused by the taker");
}

TEST(ConfigFile, TheFirstMistakeIsTold) {
  EXPECT_EQ(error_of("refused = 1\njust words\n"), "study.ini:1: refused by the taker");
  EXPECT_EQ(error_of("just words\nrefused = 1\n"),
            "study.ini:1: 'just words' is not 'key = value' (e.g. samples = 100000)");
}

TEST(ConfigFile, CapsTheLines) {
  EXPECT_EQ(error_of("a = 1\nlatitude = " + std::string(kMaxConfigLineBytes, '1') + "\n"),
            fmt::format("study.ini:2: line of {} bytes: a --config line may hold at most {} bytes",
                        kMaxConfigLineBytes + 11, kMaxConfigLineBytes));
}

TEST(ConfigFile, ADirectoryIsAReadError) { EXPECT_THROW(read_config_file("."), InputError); }

}  // namespace
}  // namespace insmc::mc
