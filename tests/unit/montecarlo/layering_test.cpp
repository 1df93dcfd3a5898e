// The include arrows between the levels of montecarlo/ (montecarlo/README.md),
// the study's layers and the diagnosis' stages point one way only
// (montecarlo/study/README.md, montecarlo/records/runs/README.md,
// montecarlo/records/gap/README.md): a change to a later stage cannot reach
// back into an earlier one.
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

/// The position of a file of montecarlo/records/gap/ in the stage order; -1 for a
/// file outside every stage.
int gap_stage(const std::string& path) {
  static const std::vector<std::string> kOrder = {
      "montecarlo/records/gap/metric/",          "montecarlo/records/gap/candidates/",       "montecarlo/records/gap/diagnosis_options.",
      "montecarlo/records/gap/diagnosis_results.", "montecarlo/records/gap/null/",         "montecarlo/records/gap/fit/",
      "montecarlo/records/gap/where/",           "montecarlo/records/gap/ranking/",          "montecarlo/records/gap/diagnosis.h",
      "montecarlo/records/gap/diagnosis.cpp",    "montecarlo/records/gap/report/",           "montecarlo/records/gap/validation/"};
  for (std::size_t i = 0; i < kOrder.size(); ++i)
    if (starts_with(path, kOrder[i])) return static_cast<int>(i);
  return -1;
}

/// The position of a file of montecarlo/study/ in its bottom-up order; -1
/// for a file outside every layer.
int study_layer(const std::string& path) {
  static const std::vector<std::vector<std::string>> kOrder = {
      {"montecarlo/study/random/", "montecarlo/study/kernels/"},
      {"montecarlo/study/sampler/"},
      {"montecarlo/study/model/"},
      {"montecarlo/study/aggregate/"},
      {"montecarlo/study/engine/"},
      {"montecarlo/study/write/"},
      {"montecarlo/study/run/"},
      {"montecarlo/study/rank/", "montecarlo/study/check/", "montecarlo/study/bench/"}};
  for (std::size_t i = 0; i < kOrder.size(); ++i)
    for (const std::string& folder : kOrder[i])
      if (starts_with(path, folder)) return static_cast<int>(i);
  return -1;
}

TEST(Layering, TheSourcesAreFound) {
  // The checks below pass vacuously on an empty tree: make sure they read it.
  EXPECT_GT(includes_under("montecarlo/records/gap").size(), 100u);
  EXPECT_GT(includes_under("montecarlo/records/runs").size(), 30u);
  EXPECT_GT(includes_under("montecarlo/study").size(), 100u);
  EXPECT_GT(includes_under("montecarlo/report").size(), 10u);
}

TEST(Layering, MontecarloIsItsThreeLevels) {
  std::vector<std::string> folders;
  for (const auto& entry : fs::directory_iterator(source_root() / "montecarlo"))
    if (entry.is_directory()) folders.push_back(entry.path().filename().string());
  std::sort(folders.begin(), folders.end());
  EXPECT_EQ(folders, (std::vector<std::string>{"records", "report", "study"}));
}

TEST(Layering, TheReportKnowsNeitherTheStudyNorTheRecords) {
  for (const Include& i : includes_under("montecarlo/report"))
    EXPECT_TRUE(starts_with(i.to, "montecarlo/report/") || starts_with(i.to, "lib/common/") ||
                starts_with(i.to, "lib/units/"))
        << i.from << " includes " << i.to;
}

TEST(Layering, TheStudyIncludesNoRecords) {
  for (const Include& i : includes_under("montecarlo/study"))
    EXPECT_FALSE(starts_with(i.to, "montecarlo/records/")) << i.from << " includes " << i.to;
}

TEST(Layering, TheRecordsTakeFromTheStudyOnlyItsStreamsAndSampler) {
  // The priors a run is drawn from (Table 3.1 through the sampler) and the
  // counter-based streams; nothing of the study's engine, runner or files.
  for (const Include& i : includes_under("montecarlo/records")) {
    if (!starts_with(i.to, "montecarlo/study/")) continue;
    EXPECT_TRUE(starts_with(i.to, "montecarlo/study/random/") || starts_with(i.to, "montecarlo/study/sampler/"))
        << i.from << " includes " << i.to;
  }
}

TEST(Layering, EveryLayerOfTheStudyIncludesOnlyLayersBelowIt) {
  int checked = 0;
  for (const Include& i : includes_under("montecarlo/study")) {
    const int from = study_layer(i.from);
    ASSERT_GE(from, 0) << i.from << " is in no layer of montecarlo/study/README.md";
    if (!starts_with(i.to, "montecarlo/study/")) continue;
    const int to = study_layer(i.to);
    ASSERT_GE(to, 0) << i.to << " is in no layer";
    EXPECT_LE(to, from) << i.from << " (a layer below) includes " << i.to << " (a layer above)";
    ++checked;
  }
  EXPECT_GT(checked, 50);
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
  for (const Include& i : includes_under("montecarlo/records/runs"))
    EXPECT_FALSE(starts_with(i.to, "montecarlo/records/gap/") || starts_with(i.to, "montecarlo/records/compensate/"))
        << i.from << " includes " << i.to;
}

TEST(Layering, CompensateUsesTheRunModelNotTheDiagnosis) {
  for (const Include& i : includes_under("montecarlo/records/compensate"))
    EXPECT_FALSE(starts_with(i.to, "montecarlo/records/gap/")) << i.from << " includes " << i.to;
}

TEST(Layering, EveryDiagnosisStageIncludesOnlyEarlierStages) {
  int checked = 0;
  for (const Include& i : includes_under("montecarlo/records/gap")) {
    const int from = gap_stage(i.from);
    ASSERT_GE(from, 0) << i.from << " is in no stage of montecarlo/records/gap/README.md";
    if (!starts_with(i.to, "montecarlo/records/gap/")) continue;
    const int to = gap_stage(i.to);
    ASSERT_GE(to, 0) << i.to << " is in no stage";
    EXPECT_LE(to, from) << i.from << " (a stage before) includes " << i.to << " (a later stage)";
    ++checked;
  }
  EXPECT_GT(checked, 50);
}

}  // namespace
