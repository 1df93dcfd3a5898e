// End-to-end tests of the accuracy metrics (docs/outputs.md, "Accuracy
// metrics"): envelope.csv's and run.json's CEP50, CEP95, 2DRMS and radial
// rate filled on the horizontal rows and empty elsewhere, the same bytes for
// any thread count, the summary's columns, --units nmi, and check's cep50,
// p95 and 2drms bounds (pass, fail with exit 1, bad input with exit 2)
// judged by one-sided upper confidence limits.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "tests/cli/run_program.h"

namespace insmc::testing {
namespace {

constexpr int kAccuracyColumns = 12;

std::vector<std::string> cells_of(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream in(line);
  for (std::string cell; std::getline(in, cell, ',');) out.push_back(cell);
  if (!line.empty() && line.back() == ',') out.emplace_back();
  return out;
}

/// Writes `text` to `name` in `dir`; its path.
std::string write_file(const TempDir& dir, const char* name, const std::string& text) {
  std::ofstream(dir.path() / name) << text;
  return (dir.path() / name).string();
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> out;
  std::stringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

TEST(Accuracy, CsvColumnsAreFilledOnHorizontalRowsAloneAndIdenticalForAnyThreadCount) {
  TempDir dir;
  const std::string common = "run --samples 3000 --seed 5 --scheme none,5.4 --grid-step 42min";
  const auto one = run_insmc(common + " --threads 1 --out " + dir.str() + "/t1");
  ASSERT_EQ(one.exit_code, 0) << one.err;
  const auto two = run_insmc(common + " --threads 2 --out " + dir.str() + "/t2");
  ASSERT_EQ(two.exit_code, 0) << two.err;
  for (const char* f : {"envelope.csv", "envelope_grid.csv"})
    EXPECT_EQ(read_file(dir.path() / "t1" / f), read_file(dir.path() / "t2" / f)) << f;
  const std::vector<std::string> lines = lines_of(read_file(dir.path() / "t1" / "envelope.csv"));
  const std::vector<std::string> header = cells_of(lines.at(0));
  ASSERT_EQ(header.size(), 15u + kAccuracyColumns);
  EXPECT_EQ(header[15], "cep50_m");
  EXPECT_EQ(header[26], "radial_rate_hi_nmiph");
  int horizontal = 0;
  for (std::size_t i = 1; i < lines.size(); ++i) {
    const std::vector<std::string> row = cells_of(lines[i]);
    ASSERT_EQ(row.size(), header.size()) << lines[i];
    const bool is_horizontal = row[3] == "horizontal";
    horizontal += is_horizontal;
    for (int c = 15; c < 15 + kAccuracyColumns; ++c)
      EXPECT_EQ(row[static_cast<std::size_t>(c)].empty(), !is_horizontal) << header[static_cast<std::size_t>(c)]
                                                                          << " in " << lines[i];
    if (!is_horizontal) continue;
    // Ordered as a percentile and its interval must be: lo <= value <= hi,
    // CEP50 < CEP95; 2DRMS = 2 RMS.
    const auto at = [&](int c) { return std::stod(row[static_cast<std::size_t>(c)]); };
    EXPECT_LE(at(16), at(15));
    EXPECT_LE(at(15), at(17));
    EXPECT_LT(at(15), at(18));
    // Cells have nine significant figures (relative rounding <= 5e-9 each),
    // so two cells computed from the same value agree to 1e-8.
    EXPECT_NEAR(at(21), 2 * at(6), 1e-8 * at(21));
    EXPECT_NEAR(at(22), 2 * at(7), 1e-8 * at(22));
    // The rate: CEP50 in n.mi. over t in hours.
    EXPECT_NEAR(at(24), at(15) / 1852 / (at(4) / 60), 1e-8 * at(24)) << lines[i];
  }
  EXPECT_EQ(horizontal, 2 * 2 * 3);  // schemes × systems × report times
}

TEST(Accuracy, JsonHasTheMetricsOnHorizontalRowsAndNullElsewhere) {
  const auto r = run_insmc("run --samples 2000 --scheme none --system 1 --grid-step 42min --format json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // Rows are written axis by axis: x, y, z, then horizontal at each time.
  const std::size_t x = r.out.find("\"axis\": \"x\"");
  const std::size_t h = r.out.find("\"axis\": \"horizontal\"");
  ASSERT_NE(x, std::string::npos);
  ASSERT_NE(h, std::string::npos);
  const std::string x_row = r.out.substr(x, r.out.find('}', x) - x);
  const std::string h_row = r.out.substr(h, r.out.find('}', h) - h);
  for (const char* key : {"cep50_m", "cep50_lo_m", "cep95_hi_m", "drms2_m", "radial_rate_nmiph", "quantile_samples"}) {
    EXPECT_TRUE(has(x_row, "\"" + std::string(key) + "\": null")) << key << "\n" << x_row;
    EXPECT_TRUE(has(h_row, "\"" + std::string(key) + "\": ")) << key << "\n" << h_row;
    EXPECT_FALSE(has(h_row, "\"" + std::string(key) + "\": null")) << key << "\n" << h_row;
  }
  EXPECT_TRUE(has(h_row, "\"quantile_samples\": 2000")) << h_row;
}

TEST(Accuracy, SummaryShowsCep50And2drmsAtTheLastReportTimeAndUnitsNmiWork) {
  const auto r = run_insmc("run --samples 2000 --scheme none,5.2");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* column : {" CEP50 84 |", " 2DRMS 84 |", " CEP/t nmi/h |"}) EXPECT_TRUE(has(r.out, column)) << r.out;
  const auto nmi = run_insmc("run --samples 2000 --scheme none --units nmi --format csv");
  ASSERT_EQ(nmi.exit_code, 0) << nmi.err;
  EXPECT_TRUE(has(nmi.out, ",rms_nmi,rms_lo_nmi,")) << nmi.out.substr(0, 300);
  EXPECT_TRUE(has(nmi.out, ",cep50_nmi,")) << nmi.out.substr(0, 300);
  const auto bad = run_insmc("run --samples 2000 --units furlong");
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_TRUE(has(bad.err, "--units = furlong: must be si, paper or nmi")) << bad.err;
}

TEST(Accuracy, CheckJudgesCep50AndP95BoundsByTheirUpperLimits) {
  TempDir dir;
  // Scheme none, system 2 at 84 min: CEP50 about 12 km, CEP95 about 23 km
  // (2000 samples); the loose bounds are twice that, the tight one a tenth.
  const std::string h = "scheme=none system=2 axis=horizontal t_min=84 ";
  const std::string loose = write_file(dir, "loose.txt", h + "cep50_m<=24000\n" + h + "p95<=25nmi\n");
  const std::string tight = write_file(dir, "tight.txt", h + "cep50<=0.7nmi\n");
  const auto pass = run_insmc("check --samples 2000 --bounds " + loose);
  EXPECT_EQ(pass.exit_code, 0) << pass.out << pass.err;
  EXPECT_TRUE(has(pass.out, "ok       line 1: scheme=none system=2 axis=horizontal t_min=84: CEP50 ")) << pass.out;
  EXPECT_TRUE(has(pass.out, "ok       line 2: scheme=none system=2 axis=horizontal t_min=84: CEP95 ")) << pass.out;
  const auto fail = run_insmc("check --samples 2000 --bounds " + tight);
  EXPECT_EQ(fail.exit_code, 1) << fail.out << fail.err;
  EXPECT_TRUE(has(fail.out, "VIOLATED line 1: scheme=none system=2 axis=horizontal t_min=84: CEP50 ")) << fail.out;
  // In the unit the bound was written in, to the digits its interval supports.
  EXPECT_TRUE(has(fail.out, "> bound 0.7 nmi")) << fail.out;
  const auto in_metres = run_insmc("check --samples 2000 --units si --bounds " + tight);
  EXPECT_TRUE(has(in_metres.out, "> bound 1296.4 m")) << in_metres.out;
}

TEST(Accuracy, CheckRefusesBadPercentileBoundsWithOneLine) {
  TempDir dir;
  const struct {
    const char* text;
    const char* message;
  } cases[] = {
      {"scheme=none system=2 axis=x t_min=84 cep50_m<=5000\n",
       ":1:38: limit 'cep50_m<=5000': cep50 is a percentile of the horizontal radial error; it needs axis=horizontal"},
      {"scheme=none system=2 axis=horizontal t_min=84 cep50<=3\n", ":1:54: cep50 = 3: a unit is required"},
      {"scheme=none system=2 axis=horizontal t_min=84 p95<=3lightyears\n", ":1:52: p95 = 3lightyears: unknown unit"},
      {"scheme=none system=2 axis=horizontal t_min=84 cep50_m>=3\n", ":1:47: limit 'cep50_m>=3': expected"},
  };
  for (const auto& c : cases) {
    const std::string path = write_file(dir, "bad.txt", c.text);
    const auto r = run_insmc("check --samples 2000 --bounds " + path);
    EXPECT_EQ(r.exit_code, 2) << c.text;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_TRUE(has(r.err, path + c.message)) << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;
  }
}

/// The estimate and the one-sided upper limit of check's line for `label`
/// ("RMS", "2DRMS"): "...: RMS 12345 m, one-sided upper 95% confidence limit 12500 m <= ...".
std::pair<double, double> check_numbers(const std::string& out, const std::string& line_no, const std::string& label) {
  for (const std::string& line : lines_of(out)) {
    if (line.find(" line " + line_no + ":") == std::string::npos) continue;
    const std::size_t at = line.find(": " + label + " ");
    const std::size_t limit = line.find("confidence limit ");
    if (at == std::string::npos || limit == std::string::npos) break;
    return {std::stod(line.substr(at + label.size() + 3)), std::stod(line.substr(limit + 17))};
  }
  ADD_FAILURE() << "no line " << line_no << " with " << label << " in\n" << out;
  return {0, 0};
}

TEST(Accuracy, CheckTakes2drmsAndJudgesByOneSidedUpperLimits) {
  TempDir dir;
  const std::string h = "scheme=none system=2 axis=horizontal t_min=84 ";
  const std::string path = write_file(dir, "b.txt", h + "rms_m<=1e7\n" + h + "2drms_m<=1e7\n" + h +
                                                       "rms_m<=1e7 confidence=0.5\n");
  const auto r = run_insmc("check --samples 2000 --units si --bounds " + path);
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_TRUE(has(r.out, "one-sided upper 95% confidence limit")) << r.out;
  const auto [rms, rms_limit] = check_numbers(r.out, "1", "RMS");
  const auto [drms2, drms2_limit] = check_numbers(r.out, "2", "2DRMS");
  // Each number is rounded to the second figure of its limit's distance
  // (at most a twentieth of it off); 2DRMS is twice the RMS, its limit too.
  const double slack = (rms_limit - rms) / 10 + (drms2_limit - drms2) / 20;
  EXPECT_NEAR(drms2, 2 * rms, slack) << r.out;
  EXPECT_NEAR(drms2_limit, 2 * rms_limit, 2 * slack) << r.out;
  // At c = 0.5 the one-sided limit is the estimate itself.
  const auto [half, half_limit] = check_numbers(r.out, "3", "RMS");
  EXPECT_EQ(half, half_limit) << r.out;
  // The one-sided 95 % limit is the two-sided 90 % interval's upper end
  // (z = 1.645), not the two-sided 95 % one's (z = 1.96): `run` on the same
  // samples gives both.
  double hi90 = 0, hi95 = 0, run_rms = 0;
  for (const char* conf : {"0.9", "0.95"}) {
    const auto run = run_insmc(std::string("run --samples 2000 --system 2 --scheme none --format csv --confidence ") + conf);
    ASSERT_EQ(run.exit_code, 0) << run.err;
    for (const std::string& line : lines_of(run.out)) {
      const auto c = cells_of(line);
      if (c.size() > 8 && c[0] == "none" && c[3] == "horizontal" && c[4] == "84") {
        run_rms = std::stod(c[6]);
        (conf == std::string("0.9") ? hi90 : hi95) = std::stod(c[8]);
      }
    }
  }
  ASSERT_GT(hi95, hi90);
  ASSERT_NEAR(run_rms, rms, (rms_limit - rms) / 10) << "the same samples";
  EXPECT_LT(std::abs(rms_limit - hi90), std::abs(rms_limit - hi95)) << r.out << hi90 << " " << hi95;
}

TEST(Accuracy, CheckRefusesAConfidenceOutsideTheOptionsRange) {
  TempDir dir;
  const std::string h = "scheme=none system=2 axis=horizontal t_min=84 rms_m<=9000 ";
  for (const char* c : {"0.9999999999999999", "1e-300", "0.4", "1"}) {
    const std::string path = write_file(dir, "c.txt", h + "confidence=" + c + "\n");
    const auto r = run_insmc("check --samples 2000 --bounds " + path);
    EXPECT_EQ(r.exit_code, 2) << c << "\n" << r.out << r.err;
    EXPECT_TRUE(has(r.err, path + ":1:70: confidence = '" + c + "': must lie in [0.5, 0.999999]")) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;
  }
}

}  // namespace
}  // namespace insmc::testing
