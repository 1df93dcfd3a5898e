// insmc compensate end to end: one unit's report from its recorded test run
// (its files and JSON, the exit
// codes of the verdict), the population envelope against `insmc run`'s
// Monte Carlo for the same settings, records written as other software
// writes them, and bad input (exit 2, one line naming the field).
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <cmath>
#include <algorithm>
#include <fstream>
#include <iomanip>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "tests/cli/csv_rows.h"
#include "tests/cli/run_program.h"

namespace insmc::testing {
namespace {

/// Records of `runs` truth-simulated units, the report's test run, system 1.
std::string simulate(const TempDir& dir, int runs, const std::string& scheme = "none") {
  const std::string path = dir.str() + "/units.csv";
  const ProgramResult r = run_insmc("simulate --runs " + std::to_string(runs) + " --scheme " + scheme +
                                    " --nav-duration 20min --out " + path);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return path;
}

/// The time of a line of a simulated record file that is a test row
/// (run,t_s,phase,...), or nothing.
std::optional<double> test_row_time(const std::string& line) {
  const std::size_t c1 = line.find(','), c2 = line.find(',', c1 + 1);
  if (line.starts_with("#") || line.starts_with("run") || line.find(",test,") != c2) return std::nullopt;
  return std::stod(line.substr(c1 + 1, c2 - c1 - 1));
}

/// The rows of estimates.csv of `compensate --scheme 5.3` on a record file.
std::vector<std::vector<std::string>> estimates_after_53(const std::string& records) {
  const TempDir out;
  EXPECT_EQ(run_insmc("compensate --records " + records + " --scheme 5.3 --out " + out.str()).exit_code, 0);
  return csv_rows(read_file(out.path() / "estimates.csv"));
}

TEST(Compensate, ReportsEachUnitWithItsFilesAndJson) {
  const TempDir dir;
  const std::string records = simulate(dir, 2);
  const std::string out = dir.str() + "/out";
  const ProgramResult r = run_insmc("compensate --records " + records + " --out " + out + " --format json");
  ASSERT_EQ(r.exit_code, 0) << r.err;  // no limit: go
  for (const char* f : {"compensate.md", "estimates.csv", "compensation.csv", "envelope.csv", "compensate.json",
                        "compensate.gp", "compensate.svg", "compensate.png"})
    EXPECT_TRUE(std::filesystem::exists(dir.path() / "out" / f)) << f;
  EXPECT_EQ(read_file(dir.path() / "out" / "compensate.json"), r.out);
  for (const char* key : {"\"units\"", "\"run\"", "\"estimates\"", "\"sigma\"", "\"schemes\"", "\"compensation\"",
                          "\"envelope\"", "\"t_min\"", "\"rms_m\"", "\"population_rms_m\"", "\"recommended\"",
                          "\"verdict\"", "\"go\": true", "\"U2_x\"", "\"torquer_radps\""})
    EXPECT_TRUE(has(r.out, key)) << key;
  // Every scheme at every report time, both runs, per axis and horizontal.
  const auto rows = csv_rows(read_file(dir.path() / "out" / "envelope.csv"));
  int at_84 = 0;
  for (const auto& row : rows)
    if (row.size() == 7 && row[2] == "84") ++at_84;
  EXPECT_EQ(at_84, 2 * 7 * 4);
  // The figure has a panel per scheme with data.
  const std::string svg = read_file(dir.path() / "out" / "compensate.svg");
  EXPECT_TRUE(has(svg, "5.1.2") && has(svg, "population") && has(svg, "<path")) << svg.substr(0, 400);
}

TEST(Compensate, AFleetGetsOneLinePerUnitBeforeTheDetailInTheUnitsAsked) {
  const TempDir dir;
  const std::string records = simulate(dir, 4);
  const ProgramResult r = run_insmc("compensate --records " + records + " --limit horizontal@20min=0.5nmi --units nmi");
  const std::size_t glance = r.out.find("## The units at a glance"), site = r.out.find("## The site and its test run");
  ASSERT_NE(glance, std::string::npos) << r.out.substr(0, 600);
  EXPECT_LT(glance, site);
  const std::string rollup = r.out.substr(glance, site - glance);
  // With a limit the line gives the scheme's worst limit (what decides), not the flight time's RMS.
  EXPECT_TRUE(has(rollup, "its worst limit: RMS (nmi) of limit")) << rollup;
  EXPECT_TRUE(has(rollup, "schemes meeting every limit")) << rollup;
  int rows = 0, go = 0;
  std::istringstream in(rollup);
  for (std::string line; std::getline(in, line);)
    if (line.rfind("|   ", 0) == 0) rows += 1, go += has(line, "| GO ");
  EXPECT_EQ(rows, 4) << rollup;
  EXPECT_TRUE(has(rollup, std::to_string(go) + " of 4 unit(s) go")) << rollup;
  // Exit 1 when any unit is no-go.
  EXPECT_EQ(r.exit_code, go == 4 ? 0 : 1) << r.err;
  EXPECT_TRUE(has(r.out, "horizontal@20min=0.5nmi: RMS (nmi), P(exceed)")) << "the verdict's table in the same unit";
  const ProgramResult no_limit = run_insmc("compensate --records " + records + " --units nmi");
  EXPECT_TRUE(has(no_limit.out, "horizontal RMS at 84 min (nmi)")) << no_limit.out.substr(0, 1500);
  // A limit beyond the earth's circumference is a typo, not a go.
  const ProgramResult absurd = run_insmc("compensate --records " + records + " --limit horizontal@84min=1e300nmi");
  EXPECT_EQ(absurd.exit_code, 2);
  EXPECT_TRUE(has(absurd.err, "LENGTH in (0, 40000 km]")) << absurd.err;
}

TEST(Compensate, TheVerdictIsItsExitCode) {
  const TempDir dir;
  const std::string records = simulate(dir, 1);
  const ProgramResult go = run_insmc("compensate --records " + records + " --limit horizontal@84min=100nmi --format csv");
  EXPECT_EQ(go.exit_code, 0) << go.err;
  const ProgramResult no_go =
      run_insmc("compensate --records " + records + " --limit horizontal@84min=100nmi --limit z@42min=1ft");
  EXPECT_EQ(no_go.exit_code, 1) << no_go.err;
  EXPECT_TRUE(has(no_go.out, "NO-GO")) << no_go.out;
  EXPECT_TRUE(has(no_go.out, "z@42min=1ft")) << no_go.out;

  // Test rows the model does not describe (one position reading tens of km off)
  // leave nothing to rest a go on, with or without limits.
  std::ifstream in(records);
  std::stringstream text;
  text << in.rdbuf();
  std::string body = text.str();
  const std::size_t row = body.find("\n0,300,test,");
  ASSERT_NE(row, std::string::npos);
  const std::size_t r_x = [&] {
    std::size_t at = row + 1;
    for (int comma = 0; comma < 6; ++comma) at = body.find(',', at) + 1;
    return at;
  }();
  body.insert(r_x, "500");  // r_x read as 500 followed by its digits
  const std::string bad = dir.str() + "/misfit.csv";
  std::ofstream(bad) << body;
  for (const std::string limits : {"", " --limit horizontal@84min=100nmi"}) {
    const ProgramResult misfit = run_insmc("compensate --records " + bad + limits);
    EXPECT_EQ(misfit.exit_code, 1) << limits << "\n" << misfit.out << misfit.err;
    EXPECT_TRUE(has(misfit.out, "NO-GO (the test rows do not fit the model)")) << misfit.out;
  }
  const ProgramResult json = run_insmc("compensate --records " + bad + " --format json");
  EXPECT_EQ(json.exit_code, 1);
  EXPECT_TRUE(has(json.out, "\"fits_model\": false") && !has(json.out, "\"go\": true")) << json.out.substr(0, 600);
}

/// The population envelope is the Monte Carlo's of `insmc run` for the same
/// settings (the report's test run, system 1, linear level): compensate's
/// value lies in run's interval, widened from 95 % to a family-wise 1e-3
/// over the 21 outputs (z = 4.07 instead of 1.96: half-width × 4.07/1.96).
TEST(Compensate, PopulationEnvelopeIsRunsMonteCarlo) {
  const TempDir dir;
  const std::string records = simulate(dir, 1);
  const ProgramResult c = run_insmc("compensate --records " + records + " --format csv");
  ASSERT_EQ(c.exit_code, 0) << c.err;
  std::map<std::pair<std::string, std::string>, double> population;
  for (const auto& row : csv_rows(c.out))
    if (row.size() == 7 && row[3] == "horizontal") population[{row[1], row[2]}] = std::stod(row[6]);
  const ProgramResult mc = run_insmc("run --samples 20000 --system 1 --fidelity linear --format csv");
  ASSERT_EQ(mc.exit_code, 0) << mc.err;
  const double widen = 4.07 / 1.96;
  int checked = 0;
  for (const auto& row : csv_rows(mc.out)) {
    if (row.size() < 9 || row[3] != "horizontal" || (row[4] != "42" && row[4] != "63" && row[4] != "84")) continue;
    const double rms = std::stod(row[6]), lo = std::stod(row[7]), hi = std::stod(row[8]);
    const auto it = population.find({row[0], row[4]});
    ASSERT_NE(it, population.end()) << row[0] << " " << row[4];
    EXPECT_GE(it->second, rms - (rms - lo) * widen) << row[0] << " at " << row[4] << " min";
    EXPECT_LE(it->second, rms + (hi - rms) * widen) << row[0] << " at " << row[4] << " min";
    ++checked;
  }
  EXPECT_EQ(checked, 21);
}

/// Records as other software writes them, from the simulator's: an unknown
/// header key, numbers to 9 digits, no nav rows, and either
///  * every optional key absent (pulse weight, resolution and filter
///    interval inferred from the rows), or
///  * the same, with f over 20 s windows (two 10 s windows summed) and r on
///    those rows and every 30 s.
std::string foreign_records(const TempDir& dir, const std::string& records, bool coarse) {
  const std::string path = dir.str() + (coarse ? "/coarse.csv" : "/foreign.csv");
  std::ifstream in(records);
  std::ofstream out(path);
  std::vector<double> last_f(3, 0.0);
  for (std::string line; std::getline(in, line);) {
    if (line.starts_with("# dv_pulse_mps") || line.starts_with("# position_resolution_m") ||
        line.starts_with("# filter_interval_s") || line.starts_with("# truth."))
      continue;
    if (line.starts_with("run,")) {
      out << "# writer=another-tool 2.1\n" << line << "\n";
      continue;
    }
    if (line.starts_with("#")) {
      out << line << "\n";
      continue;
    }
    const auto cells = csv_rows(line).front();
    if (cells[2] != "test") continue;
    const double t = std::stod(cells[1]);
    const bool f_row = !coarse || std::fmod(t + 1e-9, 20.0) < 1e-6;
    const bool r_row = !coarse || std::fmod(t + 1e-9, 30.0) < 1e-6;
    std::vector<double> f(3);
    for (int a = 0; a < 3; ++a) f[static_cast<std::size_t>(a)] = std::stod(cells[static_cast<std::size_t>(3 + a)]);
    if (f_row || r_row) {
      out << cells[0] << "," << cells[1] << "," << cells[2] << std::setprecision(9);
      for (int a = 0; a < 3; ++a) {
        const auto i = static_cast<std::size_t>(a);
        out << ",";
        if (f_row) out << (coarse ? (f[i] + last_f[i]) / 2 : f[i]);
      }
      for (int a = 0; a < 3; ++a) out << "," << std::stod(cells[static_cast<std::size_t>(6 + a)]);
      out << "\n";
    }
    last_f = f;
  }
  return path;
}

/// compensate infers what is missing and says so, and the estimates from
/// the foreign records agree with those from the full records: both are
/// estimates of the same unit's values from nested data, so they differ by
/// less than 4 of the coarser one's sigmas.
TEST(Compensate, RecordsOfOtherSoftware) {
  const TempDir dir;
  const std::string records = simulate(dir, 1);
  const auto full_est = estimates_after_53(records);
  for (const bool coarse : {false, true}) {
    const std::string file = foreign_records(dir, records, coarse);
    const TempDir out;
    const ProgramResult r = run_insmc("compensate --records " + file + " --scheme 5.3 --out " + out.str());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(has(r.out, "filter_interval_s absent")) << r.out;
    EXPECT_TRUE(has(r.out, "dv_pulse_mps absent")) << r.out;
    EXPECT_TRUE(has(r.out, "pulses of that weight")) << r.out;  // the lattice found, also in summed windows
    if (coarse) {
      EXPECT_TRUE(has(r.out, "filter interval 20 s")) << r.out;
    }
    const auto est = csv_rows(read_file(out.path() / "estimates.csv"));
    ASSERT_EQ(full_est.size(), est.size());
    for (std::size_t i = 1; i < est.size(); ++i) {
      const double v = std::stod(est[i][2]), s = std::stod(est[i][3]), v_full = std::stod(full_est[i][2]);
      EXPECT_LE(std::abs(v - v_full), 4 * s) << est[i][1] << (coarse ? " (20 s windows)" : "");
    }
  }

  // A recorder's time stamps jitter by 0.4 % of τ (10 s): the rows are the
  // grid's, and the estimates agree with the unjittered file's.
  std::ifstream in(records);
  const std::string jittered = dir.str() + "/jittered.csv";
  std::ofstream jitter(jittered);
  int test_row = 0;
  for (std::string line; std::getline(in, line);) {
    const std::size_t c1 = line.find(','), c2 = line.find(',', c1 + 1);
    if (!line.starts_with("#") && !line.starts_with("run") && line.find(",test,") == c2) {
      const double t = std::stod(line.substr(c1 + 1, c2 - c1 - 1));
      if (t < 900.0) {
        line = line.substr(0, c1 + 1) + fmt::format("{:.3f}", t + (test_row++ % 2 ? 0.04 : -0.04)) + line.substr(c2);
      }
    }
    jitter << line << "\n";
  }
  jitter.close();
  const TempDir jittered_out;
  const ProgramResult j = run_insmc("compensate --records " + jittered + " --scheme 5.3 --out " + jittered_out.str());
  ASSERT_EQ(j.exit_code, 0) << j.err;
  const auto jittered_est = csv_rows(read_file(jittered_out.path() / "estimates.csv"));
  ASSERT_EQ(full_est.size(), jittered_est.size());
  for (std::size_t i = 1; i < jittered_est.size(); ++i)
    EXPECT_LE(std::abs(std::stod(jittered_est[i][2]) - std::stod(full_est[i][2])), std::stod(full_est[i][3]))
        << jittered_est[i][1] << " (jittered time stamps)";
}

TEST(Compensate, BadInputIsRefusedWithTheFieldNamed) {
  const TempDir dir;
  const std::string records = simulate(dir, 1);
  const std::string base = "compensate --records " + records + " ";
  const std::pair<std::string, std::string> cases[] = {
      {"compensate", "--records"},
      {base + "--limit horizontal84min=3nmi", "--limit"},
      {base + "--limit north@84min=3nmi", "--limit"},
      {base + "--limit horizontal@84min=-3nmi", "--limit"},
      {base + "--limit horizontal@0min=3nmi", "--limit"},
      {base + "--limit horizontal@84min=3deg", "--limit"},
      {base + "--run 7", "--run"},
      {base + "--risk 0", "--risk"},
      {base + "--risk 0.9", "--risk"},
      {base + "--flight-time 0min", "--flight-time"},
      {base + "--flight-time 1000h", "--flight-time"},
      {base + "--site-gravity 5mps2", "--site-gravity"},
      {base + "--scheme 5.9", "--scheme"},
      {base + "--realignment-duration 100h", "--realignment-duration"},
      {"compensate --records " + dir.str() + "/absent.csv", "absent.csv"},
  };
  for (const auto& [args, field] : cases) {
    const ProgramResult r = run_insmc(args);
    EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.err;
    EXPECT_TRUE(has(r.err, field)) << args << "\n" << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
  // Records flown under 5.4, whose compensation acts from the switch-over:
  // their test rows are not an uncompensated test run.
  const TempDir d54;
  const ProgramResult s54 = run_insmc("compensate --records " + simulate(d54, 1, "5.4"));
  EXPECT_EQ(s54.exit_code, 2) << s54.err;
  EXPECT_TRUE(has(s54.err, "scheme") && has(s54.err, "5.4")) << s54.err;
  // A test run whose logger stopped from t = 200 s to 700 s: 51 of its 90
  // filter intervals missing, more than half of what it recorded; the run,
  // the counts and the first missing time are named.
  std::ifstream in(records);
  std::ofstream out(dir.str() + "/holes.csv");
  for (std::string line; std::getline(in, line);) {
    const std::optional<double> t = test_row_time(line);
    const long k = t ? std::lround(*t / 10.0) : 0;
    if (!(t && k >= 20 && k <= 70)) out << line << "\n";
  }
  out.close();
  const ProgramResult holes = run_insmc("compensate --records " + dir.str() + "/holes.csv");
  EXPECT_EQ(holes.exit_code, 2) << holes.err;
  EXPECT_TRUE(has(holes.err, "holes.csv: ") && has(holes.err, "run 0") &&
              has(holes.err, "the first missing at t = 200 s; ") &&
              has(holes.err, "f at 39 and r at 39 of the 90 filter intervals") &&
              has(holes.err, "at least 45 of the 90 intervals"))
      << holes.err;
}

TEST(Compensate, ARecorderWhoseFilterIntervalDoesNotDivideTheTestRun) {
  // A recorder of 40 s windows over a 15-min test run: the fits take the 22
  // windows that end within it (to 880 s), said so, and the rows fit. Made
  // from a 920 s simulated test run (23 windows) whose header says 900 s and
  // whose window ending at 920 s is gone.
  const TempDir dir;
  const std::string sim = dir.str() + "/sim.csv";
  ASSERT_EQ(run_insmc("simulate --runs 1 --test-duration 920s --filter-interval 40s --nav-duration 20min --out " + sim)
                .exit_code,
            0);
  std::ifstream in(sim);
  const std::string cut = dir.str() + "/cut.csv";
  std::ofstream out(cut);
  for (std::string line; std::getline(in, line);) {
    if (line == "# test_duration_s=920") line = "# test_duration_s=900";
    if (line.find(",920,test,") == std::string::npos) out << line << "\n";
  }
  out.close();
  const ProgramResult r = run_insmc("compensate --records " + cut);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(has(r.out, "the filter interval 40 s does not divide T = 900 s: the fits (4.4), (4.8) take the 22 "
                         "windows that end within the test run (to 880 s)"))
      << r.out;
  EXPECT_TRUE(has(r.out, "1 of 1 unit(s) go")) << r.out;
}

TEST(Compensate, ARunThatDroppedRecordsIsFittedOverTheIntervalsItHas) {
  // A logger that dropped five test records of 90 and the f of one more:
  // the fits (4.4), (4.8) over the rest, said so, and the unit's test rows
  // still fit the model. The conditioning on fewer rows is nested in the
  // one on all of them, so the two estimates differ by a Gaussian of
  // variance σ_dropped² − σ_all² (held to 4 of its sigmas). That variance is
  // not small: with counted ΔV pulses the windows' counting errors telescope
  // over consecutive windows, and each missing window breaks the chain
  // (about twice the sigma of Û2_z here).
  const TempDir dir;
  const std::string records = simulate(dir, 1);
  const auto full_est = estimates_after_53(records);
  std::ifstream in(records);
  const std::string dropped = dir.str() + "/dropped.csv";
  std::ofstream out(dropped);
  std::vector<std::string> header;
  for (std::string line; std::getline(in, line);) {
    if (line.starts_with("#")) {
      out << line << "\n";
      continue;
    }
    std::vector<std::string> cells;
    std::stringstream ss(line);
    for (std::string cell; std::getline(ss, cell, ',');) cells.push_back(cell);
    if (header.empty()) {
      header = cells;
      out << line << "\n";
      continue;
    }
    const auto col = [&](const char* name) {
      return static_cast<std::size_t>(std::find(header.begin(), header.end(), name) - header.begin());
    };
    const bool test_row = cells[col("phase")] == "test";
    const double t = std::stod(cells[col("t_s")]);
    if (test_row && (t == 50 || t == 130 || t == 300 || t == 610 || t == 820)) continue;
    if (test_row && t == 440)
      for (const char* f : {"f_x", "f_y", "f_z"}) cells[col(f)].clear();
    for (std::size_t i = 0; i < cells.size(); ++i) out << (i ? "," : "") << cells[i];
    out << "\n";
  }
  out.close();
  const TempDir dropped_out;
  const ProgramResult r = run_insmc("compensate --records " + dropped + " --scheme 5.3 --out " + dropped_out.str());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(has(r.out, "run 0: f at 84 and r at 85 of the 90 filter intervals of the test run (the first missing "
                         "at t = 50 s)"))
      << r.out;
  EXPECT_TRUE(has(r.out, "1 of 1 unit(s) go")) << r.out;  // no limit: no-go only where the rows do not fit
  const auto est = csv_rows(read_file(dropped_out.path() / "estimates.csv"));
  ASSERT_EQ(full_est.size(), est.size());
  for (std::size_t i = 1; i < est.size(); ++i) {
    const double sigma = std::stod(est[i][3]), sigma_all = std::stod(full_est[i][3]);
    EXPECT_GE(sigma, sigma_all * (1 - 1e-9)) << est[i][1];  // fewer data never know more
    EXPECT_LE(std::abs(std::stod(est[i][2]) - std::stod(full_est[i][2])),
              4 * std::sqrt(sigma * sigma - sigma_all * sigma_all))
        << est[i][1] << " (six of 90 intervals dropped)";
  }
}

TEST(Compensate, ALoggerOfOneSecondRecordsThatDropsOneInTenIsFitted) {
  // f and r every second, each run dropping its own tenth of the test
  // records, as a real logger does: about a third of the 10-s boxes are
  // whole (0.9^10), but each run holds nine tenths of what it recorded, so
  // it is fitted over the whole boxes and said so. Its conditioning is on a
  // subset of the boxes of the undropped file's, so the estimates differ by
  // a Gaussian of variance sigma_dropped^2 - sigma_all^2 (4 of its sigmas).
  const TempDir dir;
  const std::string records = dir.str() + "/one_second.csv";
  ASSERT_EQ(run_insmc("simulate --runs 2 --filter-interval 1s --nav-duration 20min --out " + records).exit_code, 0);
  const auto full_est = estimates_after_53(records);
  std::ifstream in(records);
  const std::string dropped = dir.str() + "/dropped.csv";
  std::ofstream out(dropped);
  long test_row = 0;
  for (std::string line; std::getline(in, line);) {
    // A scrambled tenth of the rows (a multiplicative hash of the row's index).
    if (test_row_time(line) && (static_cast<unsigned long>(test_row++) * 2654435761UL >> 7) % 10 == 3) continue;
    out << line << "\n";
  }
  out.close();
  const TempDir dropped_out;
  const ProgramResult r = run_insmc("compensate --records " + dropped + " --scheme 5.3 --out " + dropped_out.str());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(has(r.out, "; 10 s boxes summed from 1 s windows, a box with a window missing left out; 9")) << r.out;
  EXPECT_TRUE(has(r.out, "2 of 2 unit(s) go")) << r.out;  // the rows fit the model
  const auto est = csv_rows(read_file(dropped_out.path() / "estimates.csv"));
  ASSERT_EQ(full_est.size(), est.size());
  for (std::size_t i = 1; i < est.size(); ++i) {
    const double sigma = std::stod(est[i][3]), sigma_all = std::stod(full_est[i][3]);
    EXPECT_GE(sigma, sigma_all * (1 - 1e-9)) << est[i][1];
    EXPECT_LE(std::abs(std::stod(est[i][2]) - std::stod(full_est[i][2])),
              4 * std::sqrt(sigma * sigma - sigma_all * sigma_all))
        << est[i][1] << " (a tenth of the 1-s records dropped)";
  }
}

TEST(Compensate, TheRowAtTheTestRunsEndLabelledNavByItsTimeStampIsTheTestRunsLast) {
  // A recorder that reads the phase from a time stamp a little late (0.05 s,
  // within the 1 % of the recorder's 10-s spacing a stamp may jitter) labels the row
  // at T nav. Nothing reset the navigation at T, so that row is the test
  // run's last: the unit is fitted over every interval, to the bit of the
  // file stamped on time. Stamped 0.5 s late, it is no longer the row at T.
  const TempDir dir;
  const std::string records = simulate(dir, 1);
  const auto on_time = estimates_after_53(records);
  const auto restamped = [&](const std::string& stamp) {
    std::ifstream in(records);
    const std::string path = dir.str() + "/late_" + stamp + ".csv";
    std::ofstream out(path);
    for (std::string line; std::getline(in, line);) {
      if (test_row_time(line) == 900.0) line = "0," + stamp + ",nav" + line.substr(line.find(",test,") + 5);
      out << line << "\n";
    }
    return path;
  };
  const std::string late = restamped("900.05");
  EXPECT_EQ(estimates_after_53(late), on_time);
  const ProgramResult r = run_insmc("compensate --records " + late + " --scheme 5.3");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_FALSE(has(r.out, "filter intervals of the test run")) << r.out;  // none missing
  const ProgramResult too_late = run_insmc("compensate --records " + restamped("900.5") + " --scheme 5.3");
  EXPECT_EQ(too_late.exit_code, 0) << too_late.err;
  EXPECT_TRUE(has(too_late.out, "f at 89 and r at 89 of the 90 filter intervals")) << too_late.out;
}

TEST(Compensate, ARunReadAloneIsTheWholeFilesSectionWhenTheHeaderLeavesOutItsValues) {
  // The pulse weight, the resolution and the filter interval inferred from
  // the rows: from every run of the file, so that --run R reports what the
  // whole file reports for R, to the bit.
  const TempDir dir;
  const std::string records = simulate(dir, 3);
  std::ifstream in(records);
  const std::string bare = dir.str() + "/bare.csv";
  std::ofstream out(bare);
  for (std::string line; std::getline(in, line);)
    if (!line.starts_with("# dv_pulse_mps=") && !line.starts_with("# position_resolution_m=") &&
        !line.starts_with("# filter_interval_s="))
      out << line << "\n";
  out.close();
  const TempDir whole, alone;
  ASSERT_EQ(run_insmc("compensate --records " + bare + " --out " + whole.str()).exit_code, 0);
  ASSERT_EQ(run_insmc("compensate --records " + bare + " --run 1 --out " + alone.str()).exit_code, 0);
  std::vector<std::vector<std::string>> of_run_1;
  for (const auto& row : csv_rows(read_file(whole.path() / "estimates.csv")))
    if (row[0] == "1") of_run_1.push_back(row);
  auto alone_rows = csv_rows(read_file(alone.path() / "estimates.csv"));
  alone_rows.erase(alone_rows.begin());  // the header
  ASSERT_FALSE(of_run_1.empty());
  EXPECT_EQ(of_run_1, alone_rows);
  const ProgramResult absent = run_insmc("compensate --records " + bare + " --run 9");
  EXPECT_EQ(absent.exit_code, 2);
  EXPECT_TRUE(has(absent.err, "--run = 9") && has(absent.err, "3 runs, ids 0 to 2")) << absent.err;
}

}  // namespace
}  // namespace insmc::testing
