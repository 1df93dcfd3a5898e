// Replays every kept fuzz input (tests/fuzz/corpus/<target>/ and
// tests/fuzz/regressions/<target>/) through its reader in the normal build:
// each must be accepted or refused with an InputError, never crash or throw
// anything else. So every crash the fuzzers once found stays fixed, without
// clang.
#include <gtest/gtest.h>

#include <exception>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "tests/fuzz/fuzz_entry.h"

namespace insmc::fuzz {
namespace {

namespace fs = std::filesystem;

std::string read_bytes(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

class FuzzCorpus : public ::testing::TestWithParam<Target> {};

TEST_P(FuzzCorpus, EveryKeptInputIsAcceptedOrRefused) {
  const Target target = GetParam();
  int seeds = 0;
  for (const char* kind : {"corpus", "regressions"}) {
    const fs::path dir = fs::path(INSMC_FUZZ_DIR) / kind / target.name;
    if (!fs::is_directory(dir)) continue;
    for (const auto& entry : fs::directory_iterator(dir)) {
      if (!entry.is_regular_file()) continue;
      seeds += kind == std::string("corpus");
      try {
        target.run(read_bytes(entry.path()));
      } catch (const std::exception& e) {
        ADD_FAILURE() << entry.path() << ": " << e.what();
      }
    }
  }
  EXPECT_GE(seeds, 3) << "tests/fuzz/corpus/" << target.name << " needs seed inputs";
}

INSTANTIATE_TEST_SUITE_P(Readers, FuzzCorpus, ::testing::ValuesIn(kTargets),
                         [](const ::testing::TestParamInfo<Target>& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace insmc::fuzz
