// End-to-end test of `insmc gap-validate --quick` (label slow: the sanitizer
// run leaves it out; the diagnosis it drives is covered there by gap_test).
#include <gtest/gtest.h>

#include <filesystem>

#include "tests/cli/run_program.h"

namespace insmc::testing {
namespace {

bool has(const std::string& text, const std::string& what) { return text.find(what) != std::string::npos; }

TEST(GapValidate, QuickSubsetScoresEveryEffectBlind) {
  TempDir dir;
  const std::string out = (dir.path() / "v").string();
  const auto r = run_insmc("gap-validate --quick --out " + out);
  // 0 when every target holds, 1 when one fails (named on stderr).
  ASSERT_TRUE(r.exit_code == 0 || r.exit_code == 1) << r.err;
  if (r.exit_code == 1) {
    EXPECT_TRUE(has(r.err, "target not met")) << r.err;
  }
  const std::string csv = read_file(std::filesystem::path(out) / "confusion.csv");
  for (const char* e : {"none", "quantization", "sway", "accel_bias_instability", "switch_transient"})
    EXPECT_TRUE(has(csv, e)) << e;
  const std::string json = read_file(std::filesystem::path(out) / "validation.json");
  EXPECT_TRUE(has(json, "\"false_alarms\": 0")) << json.substr(0, 300);
  EXPECT_EQ(run_insmc("gap-validate --seeds 0").exit_code, 2);
}

}  // namespace
}  // namespace insmc::testing
