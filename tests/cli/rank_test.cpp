// insmc rank end to end: the order and its paired significance, the
// break-even values checked against `insmc covariance` run on either side of
// them (another path through the program than rank's polynomials), and bad
// input.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "tests/cli/csv_rows.h"
#include "tests/cli/run_program.h"

namespace insmc::testing {
namespace {

/// Horizontal RMS [m] per scheme of system `system` at `t_min` from `insmc covariance`.
std::map<std::string, double> covariance_rms(const std::string& options, int system, int t_min) {
  const ProgramResult r = run_insmc("covariance --format csv " + options);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  std::map<std::string, double> out;
  for (const auto& row : csv_rows(r.out))
    if (row.size() > 4 && row[1] == std::to_string(system) && row[2] == "horizontal" && row[3] == std::to_string(t_min))
      out[row[0]] = std::stod(row[4]);
  return out;
}

std::string first_of(const std::map<std::string, double>& rms) {
  std::string best;
  for (const auto& [scheme, value] : rms)
    if (best.empty() || value < rms.at(best)) best = scheme;
  return best;
}

TEST(Rank, ZeroSchemeErrorsPut54FirstAt84MinSignificantlyAndItsE4LimitHolds) {
  TempDir out;
  const ProgramResult r =
      run_insmc("rank --samples 4000 --dist scheme_errors=zero --quiet --out " + out.str());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto ranking = csv_rows(read_file(out.path() / "ranking.csv"));
  ASSERT_FALSE(ranking.empty());
  EXPECT_EQ(ranking[0], (std::vector<std::string>{"system", "t_min", "fidelity", "rank", "scheme", "rms_m", "rms_lo_m",
                                                  "rms_hi_m", "order_significant", "test"}));
  std::map<std::string, std::string> first;  // "system t" → first scheme
  for (std::size_t i = 1; i < ranking.size(); ++i) {
    const auto& row = ranking[i];
    ASSERT_EQ(row.size(), 10u);
    // Off the report times (the grid) no sample is kept: an order is
    // significant exactly when the two RMS intervals are disjoint.
    const bool report_time = row[1] == "42" || row[1] == "63" || row[1] == "84";
    EXPECT_EQ(row[9], report_time ? "paired" : "intervals") << row[1];
    EXPECT_NE(row[1], "0") << "t = 0 ranked";
    if (!report_time && !row[8].empty()) {
      ASSERT_LT(i + 1, ranking.size());
      const auto& next = ranking[i + 1];
      ASSERT_EQ(next[1], row[1]);
      EXPECT_EQ(row[8] == "true", std::stod(row[7]) < std::stod(next[6])) << row[0] << " " << row[1] << " " << row[4];
    }
    if (row[3] != "1") continue;
    first[row[0] + " " + row[1]] = row[4];
    // The first place at 84 min is 5.4's, ahead of the second with 4000 paired samples.
    if (row[1] == "84") {
      EXPECT_EQ(row[4], "5.4") << "system " << row[0];
      EXPECT_EQ(row[8], "true") << "system " << row[0];
      EXPECT_LE(std::stod(row[6]), std::stod(row[5]));
      EXPECT_GE(std::stod(row[7]), std::stod(row[5]));
    }
  }
  // Two systems × the 2-min grid from 2 to 90 min (45 times) and 63 min.
  EXPECT_EQ(first.size(), 2u * 46u);

  // E4's break-even value at 84 min, system 1: on either side of it
  // `covariance` puts another scheme first.
  const auto breakeven = csv_rows(read_file(out.path() / "breakeven.csv"));
  EXPECT_EQ(breakeven[0], (std::vector<std::string>{"system", "t_min", "fidelity", "assumption", "leader", "challenger",
                                                    "value", "unit"}));
  double e4 = 0;
  std::string challenger;
  for (const auto& row : breakeven)
    if (row[0] == "1" && row[1] == "84" && row[3] == "alignment_drift_error" && (e4 == 0 || std::stod(row[6]) < e4)) {
      EXPECT_EQ(row[4], "5.4");
      EXPECT_EQ(row[7], "radps");
      e4 = std::stod(row[6]);
      challenger = row[5];
    }
  ASSERT_GT(e4, 0) << "no crossing of E4 at 84 min";
  // The report's condition is E4 below about 1e-3 ω_ie (7.3e-8 rad/s); the crossing must be of that order.
  EXPECT_GT(e4, 1e-4 * 7.292115e-5);
  EXPECT_LT(e4, 1e-2 * 7.292115e-5);
  const auto first_at = [&](double factor) {
    char bound[64];
    std::snprintf(bound, sizeof bound, "%.17gmeru", e4 * factor / 7.292115e-8);
    return first_of(covariance_rms(std::string("--dist scheme_errors=zero --dist alignment_drift_error=uniform "
                                               "--bound alignment_drift_error=") + bound, 1, 84));
  };
  EXPECT_EQ(first_at(0.99), "5.4");
  EXPECT_EQ(first_at(1.01), challenger);
}

}  // namespace
}  // namespace insmc::testing

namespace insmc::testing {
namespace {

TEST(Rank, PaperUnitsPrintFeetAndTheJsonStaysSI) {
  // The same study in metres and in feet: the same order, every length
  // scaled by the foot (0.3048 m exactly), the unit named where it is printed.
  const std::string study = "rank --samples 2000 --system 1 --scheme none,5.3,5.4 --grid-step 42min --quiet --out ";
  TempDir si, ft;
  ASSERT_EQ(run_insmc(study + si.str()).exit_code, 0);
  const ProgramResult r = run_insmc(study + ft.str() + " --units paper");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto metres = csv_rows(read_file(si.path() / "ranking.csv"));
  const auto feet = csv_rows(read_file(ft.path() / "ranking.csv"));
  ASSERT_EQ(feet.size(), metres.size());
  ASSERT_GT(feet.size(), 1u);
  EXPECT_EQ(feet[0][5], "rms_ft");
  EXPECT_EQ(feet[0][7], "rms_hi_ft");
  for (std::size_t i = 1; i < feet.size(); ++i) {
    EXPECT_EQ(feet[i][4], metres[i][4]) << "the order does not depend on the unit";
    for (std::size_t c : {5u, 6u, 7u})
      EXPECT_NEAR(std::stod(feet[i][c]) * 0.3048, std::stod(metres[i][c]), 1e-6 * std::stod(metres[i][c]));
  }
  const std::string md = read_file(ft.path() / "rank.md");
  EXPECT_NE(md.find("RMS [ft] ± half-width"), std::string::npos);
  EXPECT_EQ(md.find("[m]"), std::string::npos) << "a length left in metres";
  const std::string json = read_file(ft.path() / "rank.json");
  EXPECT_NE(json.find("\"rms_m\""), std::string::npos);
  EXPECT_EQ(json.find("_ft\""), std::string::npos);
  const ProgramResult shown = run_insmc("rank --samples 2000 --system 1 --scheme none,5.4 --grid-step 42min --units paper");
  ASSERT_EQ(shown.exit_code, 0) << shown.err;
  EXPECT_NE(shown.out.find("RMS in ft"), std::string::npos) << shown.out;
}

TEST(Rank, EachOptionThatCannotApplyIsRefusedWithExit2) {
  for (const char* args : {"rank --fidelity truth", "rank --test-duration 5min,10min", "rank --samples 1",
                           "rank --alignment-time 30min", "rank --units furlong"}) {
    const ProgramResult r = run_insmc(args);
    EXPECT_EQ(r.exit_code, 2) << args << ": " << r.err;
    EXPECT_NE(r.err.find("insmc rank:"), std::string::npos) << r.err;
  }
}

// Under --units nmi every length is in nautical miles: the reset errors'
// axes in nmi and kt (not ft and ft/s), each adjacent difference's size
// beside its z, and each assumption's searched range stated.
TEST(Rank, NauticalMilesEverywhereWithEachDifferencesSizeAndTheSearchedRanges) {
  TempDir out;
  const ProgramResult r = run_insmc("rank --samples 2000 --system 1 --scheme none,5.3,5.4 --grid-step 42min --quiet "
                                    "--units nmi --out " + out.str());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string gp = read_file(out.path() / "rank.gp");
  EXPECT_EQ(gp.find("[ft"), std::string::npos) << "an axis in feet";
  EXPECT_NE(gp.find("reset_position_error [nmi]"), std::string::npos);
  EXPECT_NE(gp.find("reset_velocity_error [kt]"), std::string::npos);
  const std::string md = read_file(out.path() / "rank.md");
  EXPECT_NE(md.find("(z = "), std::string::npos);
  EXPECT_NE(md.find(" nmi larger"), std::string::npos) << md.substr(0, 3000);
  EXPECT_NE(md.find("| searched "), std::string::npos);
  // The test duration is scanned over 1 to 40 min (whole filter intervals).
  EXPECT_NE(md.find("1 to 40 min"), std::string::npos) << md;
  for (const char* sentence : {"stays first over the whole searched range of", "stays first while"})
    for (std::size_t at = md.find(sentence); at != std::string::npos; at = md.find(sentence, at + 1)) {
      const std::string rest = md.substr(at, md.find('\n', at) - at);
      EXPECT_NE(rest.find(" to "), std::string::npos) << "no range in: " << rest;
    }
}

}  // namespace
}  // namespace insmc::testing
