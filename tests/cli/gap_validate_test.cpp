// End-to-end test of `insmc gap-validate --quick` (label slow: the sanitizer
// run leaves it out; the diagnosis it drives is covered there by gap_test).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

#include "tests/cli/run_program.h"
#include "tests/cli/svg_figure.h"

namespace insmc::testing {
namespace {

TEST(GapValidate, QuickSubsetScoresEveryEffectBlind) {
  TempDir dir;
  const std::string out = (dir.path() / "v").string();
  const auto r = run_insmc("gap-validate --quick --out " + out);
  // 0 when every target holds, 1 when one fails (named on stderr). At 30x
  // every effect it detects in 10-run files must be named (fixed seed).
  EXPECT_EQ(r.exit_code, 0) << r.err;
  const std::string csv = read_file(std::filesystem::path(out) / "confusion.csv");
  for (const char* e : {"none", "quantization", "sway", "accel_bias_instability", "switch_transient"})
    EXPECT_TRUE(has(csv, e)) << e;
  const std::string json = read_file(std::filesystem::path(out) / "validation.json");
  EXPECT_TRUE(has(json, "\"false_alarms\": 0")) << json.substr(0, 300);
  // A diagnosis that lost its power would pass as "undetectable": at 30x
  // only the effects the full study (docs/gap.md) detects at 30x alone, in
  // 20-run files, may go undetected in the quick study's 10-run files.
  const std::size_t u = json.find("\"undetectable\"");
  ASSERT_NE(u, std::string::npos);
  std::string undetectable = json.substr(u, json.find(']', u) - u);
  for (const char* may : {"deflection_of_vertical", "alignment_transient", "switch_transient"}) {
    const std::size_t at = undetectable.find(std::string("\"") + may + "\"");
    if (at != std::string::npos) undetectable.erase(at, std::string(may).size() + 2);
  }
  EXPECT_EQ(undetectable.find('"', undetectable.find('[')), std::string::npos) << json;
  EXPECT_EQ(run_insmc("gap-validate --seeds 0").exit_code, 2);

  // One effect alone diagnoses the very file the whole study did: a file's
  // seed depends on its place in the study, not on what else is validated.
  const std::string one = (dir.path() / "one").string();
  const auto s = run_insmc("gap-validate --quick --null-files 0 --effect sway --out " + one);
  ASSERT_TRUE(s.exit_code == 0 || s.exit_code == 1) << s.err;
  const auto sway_row = [](const std::string& md) {
    const std::size_t at = md.find("\n| sway ", md.find("## Every file"));
    std::string row = at == std::string::npos ? std::string() : md.substr(at, md.find('\n', at + 1) - at);
    std::erase(row, ' ');  // column widths follow the table's widest cell
    return row;
  };
  const std::string full_row = sway_row(read_file(std::filesystem::path(out) / "validation.md"));
  EXPECT_FALSE(full_row.empty());
  EXPECT_EQ(sway_row(read_file(std::filesystem::path(one) / "validation.md")), full_row);
  // The confusion matrix drawn: every cell inside the frame, at least one
  // square (the sway row's; the only row of this run).
  const std::string svg = read_file(std::filesystem::path(one) / "confusion.svg");
  // The plot's frame and the colour box's: the plot is the wider.
  std::vector<Frame> frames = frames_of(svg);
  ASSERT_EQ(frames.size(), 2u);
  std::sort(frames.begin(), frames.end(), [](const Frame& a, const Frame& b) { return a.x1 - a.x0 > b.x1 - b.x0; });
  std::size_t corners = 0;
  for (const Group& g : groups_of(svg))
    for (const auto& path : g.paths)
      for (const auto& [x, y] : path) {
        EXPECT_TRUE(x >= frames[0].x0 - 0.5 && x <= frames[0].x1 + 0.5 && y >= frames[0].y0 - 0.5 &&
                    y <= frames[0].y1 + 0.5)
            << g.id << " " << x << "," << y;
        ++corners;
      }
  EXPECT_GE(corners, 4u);
  EXPECT_TRUE(has(svg, "sway"));
  EXPECT_EQ(read_file(std::filesystem::path(one) / "confusion.png").substr(1, 3), "PNG");
  const std::string one_json = read_file(std::filesystem::path(one) / "validation.json");
  EXPECT_TRUE(has(one_json, "\"sway\"")) << one_json;
  EXPECT_FALSE(has(one_json, "\"quantization\"")) << one_json;  // scored: only what was asked
}

TEST(GapValidate, FilesInAnotherRecordersLayoutAreDiagnosedAsTheyCome) {
  // Each file in its own layout (f and r on other grids, shortened runs, no
  // pulse-weight key), the layout named per file; the sway file (f every
  // 5 s, r every 30 s, continuous f at this seed) is named at 30x.
  TempDir dir;
  const std::string out = (dir.path() / "foreign").string();
  const auto r = run_insmc("gap-validate --quick --layout foreign --null-files 1 --effect sway --out " + out);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  const std::string md = read_file(std::filesystem::path(out) / "validation.md");
  EXPECT_TRUE(has(md, "another recorder's conventions")) << md.substr(0, 600);
  EXPECT_TRUE(has(md, "f every 5 s, r every 30 s")) << md;
  EXPECT_TRUE(has(read_file(std::filesystem::path(out) / "validation.json"), "\"layout\": \"foreign\""));
  EXPECT_EQ(run_insmc("gap-validate --layout alien").exit_code, 2);
  // simulate writes the same layout for a user's own checks; no scheme.
  const auto s = run_insmc("simulate --layout foreign --runs 3 --seed 2 --out " + dir.str() + "/f.csv");
  ASSERT_EQ(s.exit_code, 0) << s.err;
  const std::string text = read_file(dir.path() / "f.csv");
  EXPECT_TRUE(has(text, "# recorder=")) << text.substr(0, 300);
  EXPECT_FALSE(has(text, "dv_pulse_mps")) << text.substr(0, 300);
  EXPECT_FALSE(has(text, "truth.")) << text.substr(0, 300);
  const auto refused = run_insmc("simulate --layout foreign --scheme 5.2 --out " + dir.str() + "/g.csv");
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_TRUE(has(refused.err, "--layout")) << refused.err;
}

TEST(GapValidate, BadSubsetIsAnInputError) {
  const auto e = run_insmc("gap-validate --effect no_such_effect");
  EXPECT_EQ(e.exit_code, 2);
  EXPECT_TRUE(has(e.err, "--effect")) << e.err;
  const auto m = run_insmc("gap-validate --magnitudes 1,0");
  EXPECT_EQ(m.exit_code, 2);
  EXPECT_TRUE(has(m.err, "--magnitudes")) << m.err;
  EXPECT_EQ(run_insmc("gap-validate --magnitudes 1,x").exit_code, 2);
}

}  // namespace
}  // namespace insmc::testing
