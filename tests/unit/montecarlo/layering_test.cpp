// The include arrows between the levels and the diagnosis' stages point one
// way only (montecarlo/runs/README.md, montecarlo/gap/README.md): a change
// to a later stage cannot reach back into an earlier one.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

struct Include {
  std::string from;  ///< the including file, relative to the source root
  std::string to;    ///< the included path as written ("montecarlo/...")
};

fs::path source_root() {
  const char* env = std::getenv("INSMC_SOURCE_DIR");
  return env != nullptr && *env != '\0' ? fs::path(env) : fs::path(INSMC_DEFAULT_SOURCE_DIR);
}

/// Every project include ("lib/...", "montecarlo/...", "apps/...") of the
/// sources under `folder`.
std::vector<Include> includes_under(const std::string& folder) {
  const fs::path root = source_root();
  const std::regex include_line(R"re(^\s*#\s*include\s*"((lib|montecarlo|apps)/[^"]+)")re");
  std::vector<Include> out;
  for (const auto& entry : fs::recursive_directory_iterator(root / folder)) {
    const std::string ext = entry.path().extension().string();
    if (!entry.is_regular_file() || (ext != ".h" && ext != ".cpp")) continue;
    std::ifstream in(entry.path());
    std::string line;
    std::smatch m;
    while (std::getline(in, line))
      if (std::regex_search(line, m, include_line))
        out.push_back({fs::relative(entry.path(), root).generic_string(), m[1].str()});
  }
  return out;
}

bool starts_with(const std::string& s, const std::string& prefix) { return s.rfind(prefix, 0) == 0; }

/// The position of a file of montecarlo/gap/ in the stage order; -1 for a
/// file outside every stage.
int gap_stage(const std::string& path) {
  static const std::vector<std::string> kOrder = {
      "montecarlo/gap/metric/",          "montecarlo/gap/candidates/",       "montecarlo/gap/diagnosis_options.",
      "montecarlo/gap/diagnosis_results.", "montecarlo/gap/null/",         "montecarlo/gap/fit/",
      "montecarlo/gap/where/",           "montecarlo/gap/ranking/",          "montecarlo/gap/diagnosis.h",
      "montecarlo/gap/diagnosis.cpp",    "montecarlo/gap/report/",           "montecarlo/gap/validation/"};
  for (std::size_t i = 0; i < kOrder.size(); ++i)
    if (starts_with(path, kOrder[i])) return static_cast<int>(i);
  return -1;
}

TEST(Layering, TheSourcesAreFound) {
  // The checks below pass vacuously on an empty tree: make sure they read it.
  EXPECT_GT(includes_under("montecarlo/gap").size(), 100u);
  EXPECT_GT(includes_under("montecarlo/runs").size(), 30u);
}

TEST(Layering, LibIncludesNeitherMontecarloNorApps) {
  for (const Include& i : includes_under("lib"))
    EXPECT_TRUE(starts_with(i.to, "lib/")) << i.from << " includes " << i.to;
}

TEST(Layering, MontecarloDoesNotIncludeApps) {
  for (const Include& i : includes_under("montecarlo"))
    EXPECT_FALSE(starts_with(i.to, "apps/")) << i.from << " includes " << i.to;
}

TEST(Layering, TheRunModelIncludesNoUserOfIt) {
  for (const Include& i : includes_under("montecarlo/runs"))
    EXPECT_FALSE(starts_with(i.to, "montecarlo/gap/") || starts_with(i.to, "montecarlo/compensate/"))
        << i.from << " includes " << i.to;
}

TEST(Layering, CompensateUsesTheRunModelNotTheDiagnosis) {
  for (const Include& i : includes_under("montecarlo/compensate"))
    EXPECT_FALSE(starts_with(i.to, "montecarlo/gap/")) << i.from << " includes " << i.to;
}

TEST(Layering, EveryDiagnosisStageIncludesOnlyEarlierStages) {
  int checked = 0;
  for (const Include& i : includes_under("montecarlo/gap")) {
    const int from = gap_stage(i.from);
    ASSERT_GE(from, 0) << i.from << " is in no stage of montecarlo/gap/README.md";
    if (!starts_with(i.to, "montecarlo/gap/")) continue;
    const int to = gap_stage(i.to);
    ASSERT_GE(to, 0) << i.to << " is in no stage";
    EXPECT_LE(to, from) << i.from << " (a stage before) includes " << i.to << " (a later stage)";
    ++checked;
  }
  EXPECT_GT(checked, 50);
}

}  // namespace
