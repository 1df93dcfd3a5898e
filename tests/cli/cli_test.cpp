// End-to-end tests of the insmc command line: help, good runs, the output
// contract, determinism across thread counts, and every kind of bad input
// (exit 2, one line naming the field, no output file).
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>

#include "lib/uncertainty/catalogue.h"
#include "tests/cli/run_program.h"

namespace insmc::testing {
namespace {

int line_count(const std::string& s) { return static_cast<int>(std::count(s.begin(), s.end(), '\n')); }

TEST(Cli, HelpAndVersion) {
  const auto help = run_insmc("--help");
  EXPECT_EQ(help.exit_code, 0);
  EXPECT_NE(help.out.find("subcommands"), std::string::npos);
  const auto version = run_insmc("--version");
  EXPECT_EQ(version.exit_code, 0);
  EXPECT_EQ(version.out.rfind("insmc ", 0), 0u);
  for (const char* sub : {"run", "covariance", "check", "tables", "params", "bench", "simulate", "effects"}) {
    const auto r = run_insmc(std::string(sub) + " --help");
    EXPECT_EQ(r.exit_code, 0) << sub;
    EXPECT_NE(r.out.find("usage: insmc " + std::string(sub)), std::string::npos) << sub;
  }
}

TEST(Cli, UnknownSubcommandAndOptionAreRefused) {
  const auto a = run_insmc("frobnicate");
  EXPECT_EQ(a.exit_code, 2);
  EXPECT_EQ(line_count(a.err), 1) << a.err;
  const auto b = run_insmc("tables --no-such-option");
  EXPECT_EQ(b.exit_code, 2);
  EXPECT_EQ(line_count(b.err), 1) << b.err;
  EXPECT_NE(b.err.find("no-such-option"), std::string::npos) << b.err;
}

TEST(Cli, TablesPrintsEveryTableAndWritesFiles) {
  const auto md = run_insmc("tables");
  ASSERT_EQ(md.exit_code, 0) << md.err;
  for (const char* t : {"Table 3.1", "Table 4.1", "Table 4.2", "Table 4.3", "Table 5.1", "Table 5.2", "Figure 3.2"})
    EXPECT_NE(md.out.find(t), std::string::npos) << t;
  TempDir dir;
  const auto csv = run_insmc("tables --format csv --out " + dir.str() + "/tables");
  ASSERT_EQ(csv.exit_code, 0) << csv.err;
  EXPECT_EQ(csv.out.substr(0, csv.out.find('\n')), "table,row,column,unit,printed,computed,deviation_pct,note");
  EXPECT_EQ(read_file(dir.path() / "tables" / "tables.csv"), csv.out);
}

TEST(Cli, ParamsListsTheCatalogue) {
  const auto r = run_insmc("params --format csv --bound gyro_drift=3meru --dist accel_bias_x=zero");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(line_count(r.out), 1 + static_cast<int>(catalogue().size()));  // header + every parameter
  EXPECT_NE(r.out.find("alignment_drift_error_z,alignment_drift_error,"), std::string::npos);
  EXPECT_NE(r.out.find("gyro_drift_y,gyro_drift,ω_doy,radps,"), std::string::npos);
  EXPECT_NE(r.out.find("3 meru"), std::string::npos);
  // The Markdown names the groups --bound and --dist accept.
  const auto md = run_insmc("params");
  ASSERT_EQ(md.exit_code, 0) << md.err;
  EXPECT_NE(md.out.find("Groups ("), std::string::npos);
  EXPECT_NE(md.out.find("gyro_drift, "), std::string::npos) << md.out;
}

TEST(Cli, RandomFractionSplitsZetaAndDfAndSweeps) {
  // F of Table 3.1's ζ (1 mrad) and ∂f (0.1 mg) redrawn at each alignment, 1 − F constant.
  const auto r = run_insmc("params --format csv --random-fraction 0.2");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("misalign_align_x,misalign_align,ζ_rx,rad,0.0002,"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("misalign_const_x,misalign_const,ζ_cx,rad,0.0008,"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find(",0.02 mg,"), std::string::npos) << r.out;
  // --bound on those names wins.
  const auto b = run_insmc("params --format csv --random-fraction 0.2 --bound misalign_align=0.7mrad");
  EXPECT_NE(b.out.find("misalign_align_x,misalign_align,ζ_rx,rad,0.0007,"), std::string::npos) << b.out;
  // The default is today's half and half, bit for bit.
  const auto half = run_insmc("run --samples 2048 --scheme 5.1.1 --system 1 --random-fraction 0.5 --format csv");
  const auto plain = run_insmc("run --samples 2048 --scheme 5.1.1 --system 1 --format csv");
  ASSERT_EQ(half.exit_code, 0) << half.err;
  EXPECT_EQ(half.out, plain.out);
  // A sweep: one point per fraction; the realignment of 5.1.1 draws ζ_r, ∂f_r anew, so the split matters.
  const auto sweep = run_insmc("run --samples 2048 --scheme 5.1.1 --system 1 --random-fraction 0,1 --format csv");
  ASSERT_EQ(sweep.exit_code, 0) << sweep.err;
  EXPECT_EQ(sweep.out.substr(0, 16), "random_fraction,");
  EXPECT_NE(sweep.out.find("\n0,5.1.1,"), std::string::npos);
  EXPECT_NE(sweep.out.find("\n1,5.1.1,"), std::string::npos);
  for (const char* bad : {"1.5", "-0.1", "nan", "0,2"}) {
    const auto refused = run_insmc(std::string("run --samples 2048 --random-fraction ") + bad);
    EXPECT_EQ(refused.exit_code, 2) << bad;
    EXPECT_NE(refused.err.find("--random-fraction"), std::string::npos) << refused.err;
  }
}

TEST(Cli, RunWritesTheOutputContractAndIsIdenticalForAnyThreadCount) {
  TempDir dir;
  const std::string common = " --samples 5000 --seed 7 --grid-step 10min --scheme none,5.2";
  const auto one = run_insmc("run" + common + " --threads 1 --out " + dir.str() + "/t1");
  ASSERT_EQ(one.exit_code, 0) << one.err;
  const auto two = run_insmc("run" + common + " --threads 2 --out " + dir.str() + "/t2");
  ASSERT_EQ(two.exit_code, 0) << two.err;
  for (const char* f : {"envelope.csv", "envelope_grid.csv", "envelope.md", "envelope.gp", "envelope.svg", "envelope.png", "run.json"})
    EXPECT_TRUE(std::filesystem::exists(dir.path() / "t1" / f)) << f;
  const std::string csv = read_file(dir.path() / "t1" / "envelope.csv");
  EXPECT_EQ(csv.substr(0, csv.find('\n')),
            "scheme,system,clock,axis,t_min,n,rms_m,rms_lo_m,rms_hi_m,mean_m,std_m,min_m,max_m,p95_m,ready_time_min,"
            "cep50_m,cep50_lo_m,cep50_hi_m,cep95_m,cep95_lo_m,cep95_hi_m,drms2_m,drms2_lo_m,drms2_hi_m,"
            "radial_rate_nmiph,radial_rate_lo_nmiph,radial_rate_hi_nmiph");
  EXPECT_NE(csv.find("none,2,switchover,horizontal,84,5000,"), std::string::npos);
  EXPECT_NE(csv.find("5.2,1,test_end,x,42,5000,"), std::string::npos);
  EXPECT_EQ(line_count(csv), 1 + 2 * 2 * 3 * 4);  // schemes × systems × times × axes
  for (const char* f : {"envelope.csv", "envelope_grid.csv"})
    EXPECT_EQ(read_file(dir.path() / "t1" / f), read_file(dir.path() / "t2" / f)) << f;
  const auto paper = run_insmc("run --samples 3000 --units paper --format csv --system 1");
  ASSERT_EQ(paper.exit_code, 0) << paper.err;
  EXPECT_NE(paper.out.find("rms_ft,rms_lo_ft"), std::string::npos);
}

TEST(Cli, RunPrintsASummaryWithTheIntervalAndWhereTheFullTablesAre) {
  TempDir dir;
  const auto r = run_insmc("run --samples 3000 --out " + dir.str());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // A header line, a caption, the table (2 + 7 schemes × 2 systems) and the
  // line naming the files: a screen, not 168 rows.
  EXPECT_LE(line_count(r.out), 24) << r.out;
  EXPECT_NE(r.out.find("| scheme "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find(" 84 min |"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find(" ± "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("| 5.4 "), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("| x "), std::string::npos) << "axes are in the files only\n" << r.out;
  EXPECT_NE(r.out.find((dir.path() / "envelope.md").string()), std::string::npos) << r.out;
  // The caption is wrapped for a terminal (the table is as wide as its columns).
  const std::string before_table = r.out.substr(0, r.out.find("| scheme "));
  std::size_t line_start = 0;
  for (std::size_t end = before_table.find('\n'); end != std::string::npos; end = before_table.find('\n', line_start)) {
    const std::string line = before_table.substr(line_start, end - line_start);
    EXPECT_LE(std::count_if(line.begin(), line.end(), [](char ch) { return (ch & 0xC0) != 0x80; }), 100) << line;
    line_start = end + 1;
  }
  // The file keeps every row: schemes × systems × times × axes.
  const std::string md = read_file(dir.path() / "envelope.md");
  EXPECT_EQ(std::count(md.begin(), md.end(), '\n'), 4 + 2 + 7 * 2 * 3 * 4) << md;
  // --full: the table of every axis, as before the summary.
  const auto full = run_insmc("run --samples 3000 --full");
  ASSERT_EQ(full.exit_code, 0) << full.err;
  EXPECT_GE(line_count(full.out), 7 * 2 * 3 * 4 + 2);
  EXPECT_NE(full.out.find("| horizontal "), std::string::npos);
  EXPECT_NE(full.out.find("CEP50 ["), std::string::npos) << "the accuracy metrics on the horizontal rows";
  // Without --out the line tells how to get the full tables.
  const auto bare = run_insmc("run --samples 3000 --scheme none");
  ASSERT_EQ(bare.exit_code, 0) << bare.err;
  EXPECT_NE(bare.out.find("--out DIR"), std::string::npos) << bare.out;
}

TEST(Cli, QuietPrintsNothingAndWritesTheFiles) {
  TempDir dir;
  const auto r = run_insmc("run --samples 3000 --scheme none,5.2 --quiet --out " + dir.str());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out, "");
  EXPECT_EQ(r.err, "");
  for (const char* f : {"envelope.csv", "envelope_grid.csv", "envelope.md", "envelope.gp", "envelope.svg", "envelope.png", "run.json"})
    EXPECT_TRUE(std::filesystem::exists(dir.path() / f)) << f;
  const auto cov = run_insmc("covariance --quiet --out " + dir.str() + "/cov");
  ASSERT_EQ(cov.exit_code, 0) << cov.err;
  EXPECT_EQ(cov.out, "");
  EXPECT_TRUE(std::filesystem::exists(dir.path() / "cov" / "covariance.csv"));
  // Errors still go to stderr with exit code 2.
  const auto bad = run_insmc("run --quiet --samples 0");
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_EQ(bad.out, "");
  EXPECT_NE(bad.err.find("--samples"), std::string::npos) << bad.err;
}

TEST(Cli, CsvOnStdoutIsTheEnvelopeFileByteForByte) {
  TempDir dir;
  const auto r = run_insmc("run --samples 3000 --scheme none,5.3 --format csv --out " + dir.str());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out, read_file(dir.path() / "envelope.csv"));
  EXPECT_EQ(r.out.find(" ± "), std::string::npos);  // full precision, no rounding
  // A count in exponent form is the same count.
  const auto e = run_insmc("run --samples 3e3 --scheme none,5.3 --format csv");
  ASSERT_EQ(e.exit_code, 0) << e.err;
  EXPECT_EQ(e.out, r.out);
}

/// run.json without its wall time (the one value a rerun cannot repeat).
std::string without_elapsed(std::string json) {
  const auto at = json.find("\"elapsed_s\": ");
  if (at != std::string::npos) json.erase(at, json.find('\n', at) - at);
  return json;
}

TEST(Cli, RunFromRunJsonReproducesTheFilesByteForByte) {
  TempDir dir;
  std::ofstream(dir.path() / "study.ini") << "dv-pulse = 0.05ftps\n";
  const auto first = run_insmc("run --samples 3000 --scheme none,5.4 --bound gyro_drift=20meru --sway 5mmps,6s "
                               "--test-duration 10min --config " + dir.str() + "/study.ini --quiet --out " +
                               dir.str() + "/a");
  ASSERT_EQ(first.exit_code, 0) << first.err;
  const std::string run_json = read_file(dir.path() / "a" / "run.json");
  // Every option that made the numbers, the --config file's too, and none that only shows them.
  for (const char* kept : {"--samples=3000", "--bound=gyro_drift=20meru", "--sway=5mmps,6s", "--dv-pulse=0.05ftps"})
    EXPECT_NE(run_json.find(kept), std::string::npos) << kept;
  for (const char* left : {"--out", "--quiet", "--config"}) EXPECT_EQ(run_json.find(left), std::string::npos) << left;
  const auto again = run_insmc("run --from " + dir.str() + "/a/run.json --quiet --out " + dir.str() + "/b");
  ASSERT_EQ(again.exit_code, 0) << again.err;
  for (const char* f : {"envelope.csv", "envelope_grid.csv", "envelope.md", "envelope.gp", "envelope.svg", "envelope.png"})
    EXPECT_EQ(read_file(dir.path() / "a" / f), read_file(dir.path() / "b" / f)) << f;
  EXPECT_EQ(without_elapsed(run_json), without_elapsed(read_file(dir.path() / "b" / "run.json")));
  // An option given with --from replaces the file's.
  const auto other = run_insmc("run --from " + dir.str() + "/a/run.json --samples 2000 --format csv");
  ASSERT_EQ(other.exit_code, 0) << other.err;
  EXPECT_NE(other.out, read_file(dir.path() / "a" / "envelope.csv"));
  // A file that is not a run.json, or names an unknown option: exit 2 naming --from.
  std::ofstream(dir.path() / "bad.json") << R"({"settings": {"arguments": ["--nope=1"]}})";
  std::ofstream(dir.path() / "none.json") << R"({"settings": {}})";
  for (const char* bad : {"bad.json", "none.json"}) {
    const auto r = run_insmc("run --from " + dir.str() + "/" + bad);
    EXPECT_EQ(r.exit_code, 2) << bad;
    EXPECT_NE(r.err.find("--from"), std::string::npos) << r.err;
  }
}

TEST(Cli, ASweepWritesSweepJsonWithEveryPointAndRunsAgainFromIt) {
  TempDir dir;
  const auto r = run_insmc("run --samples 2000 --scheme none --test-duration 5min,10min --latitude 0deg,60deg "
                           "--format json --out " + dir.str());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out, read_file(dir.path() / "sweep.json"));
  std::size_t points = 0;
  for (auto at = r.out.find("\"rows\": ["); at != std::string::npos; at = r.out.find("\"rows\": [", at + 1)) ++points;
  EXPECT_EQ(points, 4u);  // the product of the two lists
  EXPECT_NE(r.out.find("\"latitude_rad\": 1.0471975511965976"), std::string::npos);
  // The accuracy metrics as in envelope.csv and run.json.
  const std::string csv = read_file(dir.path() / "sweep.csv");
  EXPECT_NE(csv.substr(0, csv.find('\n')).find(",cep50_m,cep50_lo_m,cep50_hi_m,"), std::string::npos) << csv.substr(0, 400);
  EXPECT_NE(r.out.find("\"cep50_m\": "), std::string::npos);
  const auto again = run_insmc("run --from " + dir.str() + "/sweep.json --format csv");
  ASSERT_EQ(again.exit_code, 0) << again.err;
  EXPECT_EQ(again.out, read_file(dir.path() / "sweep.csv"));
}

TEST(Cli, HelpShowsDefaultsAsTyped) {
  for (const char* sub : {"run", "covariance", "check"}) {
    const auto r = run_insmc(std::string(sub) + " --help");
    EXPECT_NE(r.out.find("(=0.95)"), std::string::npos) << sub;
    EXPECT_EQ(r.out.find("999999999"), std::string::npos) << sub << r.out;
  }
}

TEST(Cli, ReplayPrintsOneSample) {
  const auto r = run_insmc("run --samples 100 --replay 42");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("# sample 42"), std::string::npos);
  EXPECT_NE(r.out.find("gyro_drift_z,"), std::string::npos);
}

TEST(Cli, CovarianceWritesRmsAndABudgetSummingToOne) {
  TempDir dir;
  const auto r = run_insmc("covariance --out " + dir.str());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string cov = read_file(dir.path() / "covariance.csv");
  EXPECT_EQ(cov.substr(0, cov.find('\n')), "scheme,system,axis,t_min,rms_m,cep50_m,cep95_m,drms2_m,radial_rate_nmiph");
  // A horizontal row: 2DRMS = 2·RMS exactly, CEP50 < CEP95, the rate CEP50/t.
  const std::size_t h = cov.find("\nnone,1,horizontal,84,");
  ASSERT_NE(h, std::string::npos) << cov;
  std::vector<double> v;
  std::string line = cov.substr(h + 1, cov.find('\n', h + 1) - h - 1);
  for (std::size_t at = 0, i = 0; at != std::string::npos; ++i) {
    const std::size_t next = line.find(',', at);
    if (i >= 3) v.push_back(std::stod(line.substr(at, next == std::string::npos ? next : next - at)));
    at = next == std::string::npos ? next : next + 1;
  }
  ASSERT_EQ(v.size(), 6u) << line;  // t_min, rms, cep50, cep95, drms2, rate
  EXPECT_NEAR(v[4], 2 * v[1], 1e-8 * v[4]);
  EXPECT_LT(v[2], v[3]);
  EXPECT_NEAR(v[5], v[2] / (84 * 60.0) * 3600 / 1852, 1e-7 * v[5]);  // 9 significant digits written
  EXPECT_NE(cov.find("\nnone,1,x,84,"), std::string::npos);  // other axes keep empty accuracy cells
  EXPECT_NE(cov.find(",,,,\n"), std::string::npos);
  const std::string budget = read_file(dir.path() / "budget.csv");
  EXPECT_EQ(budget.substr(0, budget.find('\n')), "scheme,system,axis,t_min,parameter,variance_share");
  // stdout: the horizontal RMS per scheme × system; --full: covariance.md.
  EXPECT_LE(line_count(r.out), 24) << r.out;
  EXPECT_NE(r.out.find(" 84 min |"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find((dir.path() / "covariance.md").string()), std::string::npos) << r.out;
  const auto full = run_insmc("covariance --full");
  ASSERT_EQ(full.exit_code, 0) << full.err;
  EXPECT_EQ(full.out, read_file(dir.path() / "covariance.md"));
}

struct BadInput {
  const char* args;
  const char* names;  // text the one-line message must contain
};

TEST(Cli, BadInputGivesOneLineExitTwoAndNoOutput) {
  const BadInput cases[] = {
      {"run --bound no_such_param=1mg", "no_such_param"},
      {"run --bound gyro_drift=-1meru", "gyro_drift"},
      {"run --bound gyro_drift=nanmeru", "gyro_drift"},
      {"run --bound gyro_drift=10", "unit"},
      {"run --dist accel_bias=weird", "accel_bias"},
      {"run --samples 0", "--samples"},
      {"run --samples -3", "--samples"},
      {"run --latitude 90deg --system 2", "--latitude"},
      {"run --latitude 89.999deg --system 1 --fidelity truth --samples 4", "--latitude"},
      {"simulate --latitude 89.5deg --runs 1", "--latitude ="},
      {"run --confidence 1.5", "--confidence"},
      {"run --system 3", "--system"},
      {"run --fidelity exact", "--fidelity"},
      {"run --scheme 9.9", "--scheme"},
      {"covariance --latitude 45", "--latitude"},
      {"tables --format yaml", "--format"},
  };
  for (const BadInput& c : cases) {
    TempDir dir;
    const auto r = run_insmc(std::string(c.args) + " --out " + dir.str() + "/out");
    EXPECT_EQ(r.exit_code, 2) << c.args << "\n" << r.err;
    EXPECT_EQ(line_count(r.err), 1) << c.args << "\n" << r.err;
    EXPECT_NE(r.err.find(c.names), std::string::npos) << c.args << "\n" << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir.path() / "out")) << c.args;
  }
}

TEST(Cli, CheckExitsByTheBoundsVerdict) {
  TempDir dir;
  const auto write = [&](const char* name, const char* text) {
    std::ofstream(dir.path() / name) << text;
    return (dir.path() / name).string();
  };
  const std::string loose = write("loose.txt", "# generous\nscheme=none system=2 axis=horizontal t_min=84 rms_m<=1e7\n");
  const std::string tight = write("tight.txt", "scheme=none system=1 axis=x t_min=42 rms_ft<=1 confidence=0.99\n");
  const std::string bad = write("bad.txt", "scheme=none system=1 axis=sideways t_min=42 rms_m<=1\n");
  EXPECT_EQ(run_insmc("check --samples 3000 --bounds " + loose).exit_code, 0);
  const auto violated = run_insmc("check --samples 3000 --bounds " + tight);
  EXPECT_EQ(violated.exit_code, 1);
  EXPECT_NE(violated.out.find("VIOLATED line 1"), std::string::npos) << violated.out;
  const auto malformed = run_insmc("check --samples 3000 --bounds " + bad);
  EXPECT_EQ(malformed.exit_code, 2);
  EXPECT_NE(malformed.err.find("bad.txt:1:"), std::string::npos) << malformed.err;
}

TEST(Cli, TruthFidelityRunsAndIsIdenticalForAnyThreadCount) {
  const std::string common = "run --fidelity truth --scheme none --samples 1500 --grid-step 30min --format csv";
  const auto one = run_insmc(common + " --threads 1");
  const auto two = run_insmc(common + " --threads 2");
  ASSERT_EQ(one.exit_code, 0) << one.err;
  EXPECT_EQ(one.out, two.out);
  EXPECT_NE(one.out.find("none,2,switchover,horizontal,84,1500,"), std::string::npos);
}

TEST(Cli, TruthFidelityRunsEverySchemeIdenticallyForAnyThreadCount) {
  const std::string common = "run --fidelity truth --scheme all --samples 40 --grid-step 42min --format csv";
  const auto one = run_insmc(common + " --threads 1");
  const auto two = run_insmc(common + " --threads 2");
  ASSERT_EQ(one.exit_code, 0) << one.err;
  EXPECT_EQ(one.out, two.out);
  for (const char* row : {"5.1.1,1,realignment,horizontal,84,40,", "5.2,2,test_end,horizontal,84,40,",
                          "5.4,1,switchover,z,42,40,", "combined,2,realignment,x,84,40,"})
    EXPECT_NE(one.out.find(row), std::string::npos) << row << "\n" << one.out;
}

TEST(Cli, BenchJsonIsTheJsonAloneWithEveryPath) {
  // Smallest sizes: this checks the output contract, never the speeds.
  const auto r = run_insmc("bench --samples 1024 --pipeline-samples 1024 --truth-samples 1024 --threads 1 "
                           "--rounds 1 --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  ASSERT_FALSE(r.out.empty());
  EXPECT_EQ(r.out.front(), '{');
  EXPECT_EQ(r.out.substr(r.out.find_last_not_of('\n')), "}\n");  // nothing after the JSON
  for (const char* key : {"\"median_engine_over_floor\"", "\"median_paper_full_over_floor\"",
                          "\"median_linear_over_floor\"", "\"median_truth_over_reference\"",
                          "\"truth_reference_samples_per_s\"", "\"pipeline_floor_samples_per_s\""})
    EXPECT_NE(r.out.find(key), std::string::npos) << key;
  const auto bad = run_insmc("bench --truth-samples 10");
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("--truth-samples"), std::string::npos) << bad.err;
}

TEST(Cli, SimulateWritesRecordsThatAreDeterministicPerSeed) {
  TempDir dir;
  const std::string a = (dir.path() / "a.csv").string(), b = (dir.path() / "b.csv").string();
  ASSERT_EQ(run_insmc("simulate --runs 2 --seed 3 --effect accel_bias_instability --out " + a).exit_code, 0);
  ASSERT_EQ(run_insmc("simulate --runs 2 --seed 3 --effect accel_bias_instability --out " + b).exit_code, 0);
  const std::string text = read_file(a);
  EXPECT_EQ(text, read_file(b));
  EXPECT_EQ(text.rfind("# insmc-record v1\n", 0), 0u);
  EXPECT_NE(text.find("# truth.effect.0=accel_bias_instability:"), std::string::npos);
  EXPECT_NE(text.find("\n1,6300,nav,"), std::string::npos);  // run 1 ends at T + 90 min
  const auto effects = run_insmc("effects --format csv");
  EXPECT_EQ(effects.exit_code, 0);
  EXPECT_NE(effects.out.find("gyro_drift_instability"), std::string::npos);
  for (const char* bad : {"--effect no_such_effect", "--effect sway:accel_rms=-1mg", "--runs 0", "--scheme 5.9"}) {
    const auto r = run_insmc(std::string("simulate ") + bad + " --out " + (dir.path() / "bad.csv").string());
    EXPECT_EQ(r.exit_code, 2) << bad << r.err;
    EXPECT_EQ(line_count(r.err), 1) << bad << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir.path() / "bad.csv")) << bad;
  }
}

TEST(Cli, SimulateAppliesEverySchemeOnTheRecordsClock) {
  TempDir dir;
  const std::string realigned = (dir.path() / "r.csv").string(), reset = (dir.path() / "z.csv").string();
  ASSERT_EQ(run_insmc("simulate --runs 2 --scheme 5.1.1 --out " + realigned).exit_code, 0);
  ASSERT_EQ(run_insmc("simulate --runs 2 --scheme 5.2 --out " + reset).exit_code, 0);
  // 5.1.1: realigned for 10 min after T = 15 min, switched over again at 1500 s.
  const std::string r = read_file(realigned);
  EXPECT_NE(r.find("# scheme=5.1.1\n"), std::string::npos);
  EXPECT_NE(r.find("# nav_start_s=1500\n"), std::string::npos);
  EXPECT_NE(r.find("\n0,900,test,"), std::string::npos);
  EXPECT_EQ(r.find("\n0,910,"), std::string::npos);  // nothing during the realignment
  EXPECT_NE(r.find("\n0,1510,nav,"), std::string::npos);
  EXPECT_NE(r.find("\n1,6900,nav,"), std::string::npos);
  // 5.2: reset at T, rows go on at T + τ.
  const std::string z = read_file(reset);
  EXPECT_NE(z.find("\n1,910,nav,"), std::string::npos);
  EXPECT_EQ(z.find("nav_start_s"), std::string::npos);
  // The fine alignment in the time domain (truth level only).
  const std::string aligned = (dir.path() / "a.csv").string();
  EXPECT_EQ(run_insmc("simulate --runs 1 --scheme 5.4 --alignment-time 20min --out " + aligned).exit_code, 0);
  const auto linear = run_insmc("run --samples 10 --alignment-time 20min");
  EXPECT_EQ(linear.exit_code, 2);
  EXPECT_NE(linear.err.find("--alignment-time"), std::string::npos) << linear.err;
  // The diagnosis takes records after a scheme (tests/cli/gap_test.cpp).
  const auto gap = run_insmc("gap --records " + reset);
  EXPECT_EQ(gap.exit_code, 0) << gap.err;
}

}  // namespace
}  // namespace insmc::testing
