// The plots as gnuplot renders them (montecarlo/report/plot/): each panel's
// frame holds every drawn element, each legend line has its data inside
// the frame (not collapsed onto an edge, not empty), the PNG is a PNG, and
// the shipped script renders the same SVG again.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include "tests/cli/run_program.h"
#include "tests/cli/svg_figure.h"

namespace insmc::testing {
namespace {

/// Checks one rendered figure with `panels` panels and `lines` curves in all
/// (panel_figure.h: band, curve and marks per line); for a bar figure
/// (bar_figure.h: one element per series and panel) `lines` counts those.
void expect_data_inside_frames(const std::string& svg, std::size_t panels, std::size_t lines, bool bars = false) {
  const std::vector<Frame> frames = frames_of(svg);
  ASSERT_EQ(frames.size(), panels);
  std::size_t named = 0;
  std::set<std::string> curves;
  for (const Group& g : groups_of(svg)) {
    const std::size_t panel = static_cast<std::size_t>(g.id.back() - 'a');
    ASSERT_LT(panel, frames.size()) << g.id;
    const Frame& f = frames[panel];
    // Everything inside the frame but the key's samples: with the key under
    // the axes, a line's sample is a horizontal two-point subpath below it.
    std::vector<std::pair<double, double>> points;
    for (const auto& path : g.paths) {
      const bool key_sample = path.size() == 2 && path[0].second == path[1].second && path[0].second > f.y1 + 0.5;
      if (!key_sample) points.insert(points.end(), path.begin(), path.end());
    }
    for (const auto& [x, y] : points) {
      EXPECT_GE(x, f.x0 - 0.5) << g.id << " " << g.title;
      EXPECT_LE(x, f.x1 + 0.5) << g.id << " " << g.title;
      EXPECT_GE(y, f.y0 - 0.5) << g.id << " " << g.title;
      EXPECT_LE(y, f.y1 + 0.5) << g.id << " " << g.title;
    }
    // Each line is drawn as three elements, band, curve and marks
    // (panel_figure.cpp): the curve is the second. gnuplot draws an opaque
    // key's elements twice; each is counted once.
    const int element = std::stoi(g.id.substr(std::string("gnuplot_plot_").size()));
    if ((!bars && (element - 1) % 3 != 1) || !curves.insert(g.id).second) continue;
    ++named;
    if (bars) {  // each bar a box on the axis: some must rise above it
      EXPECT_TRUE(std::any_of(points.begin(), points.end(), [&](const auto& p) { return p.second < f.y1 - 1; }))
          << g.id;
      continue;
    }
    // A curve drawn across the panel: at least half its points strictly
    // between the top and bottom edges (not clipped flat onto one).
    const auto inside = std::count_if(points.begin(), points.end(), [&](const auto& p) {
      return p.second > f.y0 + 0.5 && p.second < f.y1 - 0.5;
    });
    EXPECT_GE(points.size(), 2u) << g.title;
    EXPECT_GE(2 * static_cast<std::size_t>(inside), points.size()) << g.title;
  }
  EXPECT_EQ(named, lines);
}

void expect_png(const std::string& png) {
  ASSERT_GE(png.size(), 1000u);
  EXPECT_EQ(png.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
}

TEST(Plots, EnvelopeHasAPanelPerSchemeWithEveryLineInsideItsFrame) {
  TempDir out;
  const ProgramResult r = run_insmc("run --samples 300 --scheme none,5.1.1,5.4 --out " + out.str() + " --quiet");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string svg = read_file(out.path() / "envelope.svg");
  expect_data_inside_frames(svg, 3, 12);  // 3 schemes x 2 systems x (Monte Carlo, covariance)
  expect_png(read_file(out.path() / "envelope.png"));
  // The marks at the report times: 42, 63 and 84 min labelled in each panel.
  for (const char* t : {">42<", ">63<", ">84<"}) EXPECT_NE(svg.find(t), std::string::npos) << t;
  // The script is the figure: gnuplot run on it again gives the same SVG.
  const ProgramResult again = run_shell("cd " + out.str() + " && mkdir again && cp envelope.gp again/ && cd again && "
                                        "gnuplot envelope.gp");
  ASSERT_EQ(again.exit_code, 0) << again.err;
  EXPECT_EQ(read_file(out.path() / "again" / "envelope.svg"), svg);
}

TEST(Plots, TheErrorBudgetHasBarsPerSystemInEachSchemesFrame) {
  TempDir out;
  const ProgramResult r = run_insmc("covariance --scheme none,5.4 --out " + out.str() + " --quiet");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string svg = read_file(out.path() / "budget.svg");
  expect_data_inside_frames(svg, 2, 4, true);  // 2 schemes x 2 systems
  EXPECT_NE(svg.find("gyro drift x (ω_dox)"), std::string::npos);  // a source named on the axis, with its symbol
  expect_png(read_file(out.path() / "budget.png"));
}

// Without any error source the shares have nothing to draw: each scheme's
// panel stays, empty and saying why (gnuplot cannot autoscale a plot
// without a point, so the empty panel has its own ranges).
TEST(Plots, AnErrorFreeBudgetKeepsItsPanelsEmptyWithANote) {
  TempDir out;
  const ProgramResult r = run_insmc("covariance --scheme none,5.4 --dist all=zero --dv-pulse 0mps "
                                    "--position-resolution 0m --torquer-pulse 0rad --out " + out.str() + " --quiet");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string svg = read_file(out.path() / "budget.svg");
  EXPECT_EQ(frames_of(svg).size(), 2u);
  for (const Group& g : groups_of(svg)) EXPECT_TRUE(g.paths.empty()) << g.id;  // no bars
  EXPECT_NE(svg.find("no error source"), std::string::npos);
  expect_png(read_file(out.path() / "budget.png"));
}

TEST(Plots, Figure3Point2IsDrawnOnALogAxisWithEveryTerm) {
  TempDir out;
  const ProgramResult r = run_insmc("tables --out " + out.str());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string svg = read_file(out.path() / "fig3_2.svg");
  expect_data_inside_frames(svg, 1, 5);  // δV(0), U2, U3, U4, U5
  EXPECT_NE(svg.find("1e+03"), std::string::npos);  // decade labels of the log axis
  expect_png(read_file(out.path() / "fig3_2.png"));
}

TEST(Plots, WithoutGnuplotTheFolderIsRefusedBeforeTheWork) {
  TempDir out;
  const ProgramResult r = run_shell("PATH=/nonexistent " + insmc_path() + " run --samples 200 --out " + out.str() + "/r");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_TRUE(has(r.err, "gnuplot is not on PATH")) << r.err;
  EXPECT_TRUE(has(r.err, "gnuplot-nox")) << r.err;
  EXPECT_FALSE(std::filesystem::exists(out.path() / "r" / "envelope.csv"));
}

TEST(Plots, AProductSweepDrawsEveryLineInTheUnitsGiven) {
  TempDir out;
  const ProgramResult r = run_insmc("run --samples 200 --scheme 5.2 --system 1 --test-duration 5min,10min,20min "
                                    "--latitude 0deg,60deg --out " + out.str() + " --quiet");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string svg = read_file(out.path() / "sweep.svg");
  expect_data_inside_frames(svg, 1, 2);  // one scheme; system 1 at two latitudes
  EXPECT_NE(svg.find("test_duration [min]"), std::string::npos);
  EXPECT_NE(svg.find("system 1, latitude 60deg"), std::string::npos);
  expect_png(read_file(out.path() / "sweep.png"));
}

}  // namespace
}  // namespace insmc::testing

namespace insmc::testing {
namespace {

TEST(Plots, RankDrawsEveryAssumptionWithEachSchemesCurveInsideItsFrame) {
  TempDir out;
  const ProgramResult r =
      run_insmc("rank --samples 1000 --system 1 --scheme none,5.1.2,5.4 --quiet --out " + out.str());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string svg = read_file(out.path() / "rank.svg");
  // Six assumptions × one system, two schemes each (none, which no assumption moves, is left out).
  expect_data_inside_frames(svg, 6, 12);
  expect_png(read_file(out.path() / "rank.png"));
  EXPECT_NE(svg.find("alignment_drift_error [meru]"), std::string::npos);
}

}  // namespace
}  // namespace insmc::testing

namespace insmc::testing {
namespace {

// A sweep says what it ran (quantity, points, samples, seed), every report
// time, and the files it wrote; its labels and CSV carry the unit typed
// beside SI; each system its own colour in the figure.
TEST(Plots, ASweepSaysWhatItRanAndWroteInTheUnitTyped) {
  TempDir out;
  const ProgramResult r =
      run_insmc("run --samples 500 --bound gyro_drift=1meru,3meru --scheme 5.2 --out " + out.str());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(has(r.out, "insmc run: sweep of gyro_drift.bound over 2 points, 500 samples each, seed 1")) << r.out;
  for (const char* column : {"RMS [m] 42 min", "RMS [m] 63 min", "RMS [m] 84 min"}) EXPECT_TRUE(has(r.out, column)) << r.out;
  EXPECT_TRUE(has(r.out, "| gyro_drift.bound=1meru |")) << r.out;
  EXPECT_TRUE(has(r.out, "Files written in " + out.str() + ": sweep.csv")) << r.out;
  const std::string csv = read_file(out.path() / "sweep.csv");
  EXPECT_EQ(csv.substr(0, csv.find(",scheme")), "gyro_drift.bound_radps,gyro_drift.bound_meru");
  EXPECT_TRUE(has(csv, "\n7.292115e-08,1,5.2,1,")) << csv.substr(0, 300);
  const std::string svg = read_file(out.path() / "sweep.svg");
  EXPECT_TRUE(has(svg, "rgb(  0, 114, 178)") && has(svg, "rgb(213,  94,   0)")) << "one colour per system";
  EXPECT_TRUE(has(svg, "gyro_drift.bound [meru]"));
  // Values typed in the SI unit: no second column of the same name; °/h spelled out.
  const ProgramResult si = run_insmc("run --samples 300 --scheme 5.2 --system 1 --test-duration 300s,600s --format csv");
  ASSERT_EQ(si.exit_code, 0) << si.err;
  EXPECT_EQ(si.out.substr(0, si.out.find(",scheme")), "test_duration_s");
  const ProgramResult degrees =
      run_insmc("run --samples 300 --scheme 5.2 --system 1 --bound gyro_drift=0.01°/h,0.02°/h --format csv");
  ASSERT_EQ(degrees.exit_code, 0) << degrees.err;
  EXPECT_EQ(degrees.out.substr(0, degrees.out.find(",scheme")), "gyro_drift.bound_radps,gyro_drift.bound_deg_per_h");
}

// A logarithmic sweep's axis ends where its data end (not at the next
// decade): the last point on the frame's right edge.
TEST(Plots, ALogarithmicSweepsAxisEndsAtItsData) {
  TempDir out;
  const ProgramResult r = run_insmc("run --samples 300 --scheme 5.2 --system 1 "
                                    "--bound gyro_drift=1meru,2meru,5meru,10meru,20meru --quiet --out " + out.str());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string svg = read_file(out.path() / "sweep.svg");
  const std::vector<Frame> frames = frames_of(svg);
  ASSERT_EQ(frames.size(), 1u);
  double rightmost = 0;
  for (const Group& g : groups_of(svg))
    for (const auto& path : g.paths)
      for (const auto& [x, y] : path)
        if (y >= frames[0].y0 && y <= frames[0].y1) rightmost = std::max(rightmost, x);
  EXPECT_NEAR(rightmost, frames[0].x1, 1.0);
}

// compensate draws the limit it was given, in the unit asked for.
TEST(Plots, CompensateDrawsItsLimitInTheUnitsAsked) {
  TempDir dir;
  const std::string records = dir.str() + "/units.csv";
  ASSERT_EQ(run_insmc("simulate --runs 2 --scheme 5.3 --out " + records).exit_code, 0);
  const ProgramResult r = run_insmc("compensate --records " + records + " --scheme 5.3 --limit horizontal@84min=2nmi "
                                    "--units nmi --out " + dir.str() + "/c");
  ASSERT_LE(r.exit_code, 1) << r.err;  // go or no-go
  const std::string svg = read_file(dir.path() / "c" / "compensate.svg");
  EXPECT_TRUE(has(svg, "limit 2nmi at 84 min")) << "the limit in the legend";
  EXPECT_TRUE(has(svg, "horizontal RMS [nmi]"));
  // The limit's marker at 84 min and 2 (n.mi.), inside the frame.
  EXPECT_GE(plotted_points_inside(svg, "compensate"), 4u);
}

// --fit-u4 auto (the default) starts fitting U4 along a test-duration
// sweep of system 1 between 15 and 20 min, and 5.1.2's RMS steps up there:
// the summary, sweep.md, sweep.json and the figure say where the estimator
// changes; with the estimator held (--fit-u4 no) nothing is said.
TEST(Plots, ASweepSaysWhereADefaultChangesTheEstimator) {
  TempDir out;
  const ProgramResult r =
      run_insmc("run --samples 300 --scheme 5.1.2 --system 1 --test-duration 15min,20min --out " + out.str());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string said = "The estimators change along the sweep (--fit-u4 auto";
  EXPECT_TRUE(has(r.out, said)) << r.out;
  EXPECT_TRUE(has(r.out, "at test_duration=15min, ")) << r.out;
  EXPECT_TRUE(has(r.out, "U4 at test_duration=20min")) << r.out;
  EXPECT_TRUE(has(read_file(out.path() / "sweep.md"), said));
  EXPECT_TRUE(has(read_file(out.path() / "sweep.json"), "\"estimator_switches\""));
  const std::string gp = read_file(out.path() / "sweep.gp");
  EXPECT_TRUE(has(gp, "set arrow from 20, graph 0 to 20, graph 1")) << "the switch marked at 20 min";
  EXPECT_TRUE(has(gp, "where the estimators start fitting other terms"));
  const ProgramResult held =
      run_insmc("run --samples 300 --scheme 5.1.2 --system 1 --test-duration 15min,20min --fit-u4 no");
  ASSERT_EQ(held.exit_code, 0) << held.err;
  EXPECT_FALSE(has(held.out, "The estimators change")) << held.out;
}

}  // namespace
}  // namespace insmc::testing
