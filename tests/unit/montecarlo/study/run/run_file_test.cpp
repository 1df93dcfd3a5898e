// run.json read back for `run --from` (montecarlo/study/run/run_file.h):
// settings.arguments alone, and every way a text can fail to hold them.
#include "montecarlo/study/run/run_file.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "tests/unit/input_error_of.h"

namespace insmc::mc {
namespace {

std::string error_of(const std::string& text) {
  return test::input_error_of([&] { run_arguments_from_json(text, "run.json"); });
}

TEST(RunFile, ReadsSettingsArgumentsAlone) {
  const std::string text = R"({"envelope": [{"arguments": ["--x"]}], "settings": {"samples": 5, "arguments": )"
                           R"(["--samples=5", "--bound=gyro_drift=3meru"], "other": {"arguments": 1}}})";
  EXPECT_EQ(run_arguments_from_json(text, "run.json"),
            (std::vector<std::string>{"--samples=5", "--bound=gyro_drift=3meru"}));
}

TEST(RunFile, RefusesWhatIsNotARunFile) {
  EXPECT_EQ(error_of("not json"), "--from = run.json: is not JSON (a run.json written by insmc run)");
  EXPECT_EQ(error_of(R"({"settings": {}})"),
            "--from = run.json: has no settings.arguments array (a run.json of insmc run 0.1.0 or later)");
  EXPECT_EQ(error_of(R"({"settings": {"arguments": ["--a", 5]}})"),
            "--from = run.json: settings.arguments[1] must be an option \"--name=value\" of at most 65536 bytes");
  EXPECT_EQ(error_of(R"({"settings": {"arguments": ["samples=5"]}})"),
            "--from = run.json: settings.arguments[0] must be an option \"--name=value\" of at most 65536 bytes");
  EXPECT_EQ(error_of(R"({"settings": {"arguments": [], "arguments": []}})"),
            "--from = run.json: holds settings.arguments twice");
  EXPECT_EQ(error_of(std::string(40, '[') + std::string(40, ']')),
            "--from = run.json: has no settings.arguments array (a run.json of insmc run 0.1.0 or later)");
  EXPECT_EQ(error_of("{\"a\":" + std::string(40, '[') + std::string(40, ']') + "}"),
            "--from = run.json: nests deeper than 32 levels (insmc writes 4)");
}

}  // namespace
}  // namespace insmc::mc
