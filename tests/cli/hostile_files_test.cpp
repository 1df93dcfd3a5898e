// Hostile files and paths, end to end: files that carry options, outputs
// that name inputs or hide links, inputs far larger or longer than their
// bytes suggest, and a plotting program that dies. Each case ends with exit
// 0, 1 or 2 (never a signal, never exit 3), within 60 s and under 1 GB of
// resident memory; a refusal is one line and writes nothing.
#include <gtest/gtest.h>

#include <sys/stat.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <csignal>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <string>
#include <thread>

#include "tests/cli/run_program.h"

namespace insmc::testing {
namespace {

namespace fs = std::filesystem;

constexpr long kMaxRssKb = 1L << 20;  // 1 GB
constexpr int kMaxSeconds = 60;

std::string write(const TempDir& dir, const std::string& name, const std::string& text) {
  std::ofstream(dir.path() / name, std::ios::binary) << text;
  return (dir.path() / name).string();
}

/// Exit 2, one line naming `names`, within the limits.
void expect_refused(const std::string& args, const std::string& names) {
  const ProgramResult r = run_limited(args, kMaxSeconds);
  EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << args << "\n" << r.err;
  EXPECT_NE(r.err.find(names), std::string::npos) << args << "\n" << r.err;
  EXPECT_LT(r.peak_rss_kb, kMaxRssKb) << args;
}

TEST(HostileFiles, FilesOfOptionsDefineTheStudyAndNothingElse) {
  TempDir dir;
  const std::string elsewhere = dir.str() + "/elsewhere";
  const auto run_json = [&](const std::string& name, const std::string& argument) {
    return write(dir, name, "{\"settings\": {\"arguments\": [\"--samples=2048\", \"" + argument + "\"]}}");
  };
  expect_refused("run --from " + run_json("help.json", "--help"), "holds --help");
  expect_refused("run --from " + run_json("out.json", "--out=" + elsewhere), "holds --out");
  expect_refused("run --from " + run_json("ck.json", "--checkpoint=" + elsewhere + ".ck"), "holds --checkpoint");
  expect_refused("run --from " + run_json("format.json", "--format=csv"), "holds --format");
  // Nesting far deeper than insmc writes is refused as it is met.
  std::string deep = "{\"x\": " + std::string(100000, '[') + std::string(100000, ']') + "}";
  expect_refused("run --from " + write(dir, "deep.json", deep), "nests deeper");
  expect_refused("run --config " + write(dir, "help.ini", "help = true\n"), "help.ini:1: help");
  expect_refused("run --config " + write(dir, "from.ini", "from = " + dir.str() + "/help.json\n"), "from.ini:1: from");
  expect_refused("run --config " + write(dir, "out.ini", "samples = 2048\nout = " + elsewhere + "\n"), "out.ini:2: out");
  expect_refused("run --config " + write(dir, "nested.ini", "config = " + dir.str() + "/out.ini\n"),
                 "nested.ini:1: config");
  EXPECT_FALSE(fs::exists(elsewhere));
  EXPECT_FALSE(fs::exists(elsewhere + ".ck"));
}

TEST(HostileFiles, NoOutputReplacesAnInput) {
  TempDir dir;
  std::string imu = "gyro_x_dps,gyro_y_dps,gyro_z_dps,acc_x_g,acc_y_g,acc_z_g\n";
  for (int k = 0; k < 100 * 400; ++k) imu += "0.001,0.002,0.003,0.0001,0.0002,-1\n";
  const std::string raw = write(dir, "raw.csv", imu);
  fs::create_symlink(raw, dir.path() / "alias.csv");
  const std::string import = " --rate 100Hz --latitude 51deg --align-duration 60s --test-duration 2min --nav-duration 2min";
  expect_refused("import-imu --input " + raw + " --out " + raw + import, "an output may not replace an input");
  expect_refused("import-imu --input " + dir.str() + "/alias.csv --out " + raw + import, "is the file of --input");
  EXPECT_EQ(read_file(raw), imu) << "the raw file is untouched";
  // A record file kept in gap's output folder under one of its names.
  ASSERT_EQ(run_insmc("simulate --runs 5 --nav-duration 10min --out " + dir.str() + "/gap.json").exit_code, 0);
  const std::string records = read_file(dir.path() / "gap.json");
  expect_refused("gap --records " + dir.str() + "/gap.json --rank never --out " + dir.str(), "is the file of --records");
  EXPECT_EQ(read_file(dir.path() / "gap.json"), records);
  // A study's run.json read again into the folder that holds it: the
  // command line is rebuilt from the file, and the file stays an input.
  const fs::path study = dir.path() / "study";
  ASSERT_EQ(run_insmc("run --samples 2048 --quiet --out " + study.string()).exit_code, 0);
  const std::string run_json = read_file(study / "run.json");
  expect_refused("run --from " + (study / "run.json").string() + " --quiet --out " + study.string(), "is the file of --from");
  EXPECT_EQ(read_file(study / "run.json"), run_json);
}

TEST(HostileFiles, PlantedLinksAreRefusedBeforeTheWork) {
  TempDir dir;
  ASSERT_EQ(run_insmc("simulate --runs 20 --out " + dir.str() + "/runs.csv").exit_code, 0);
  std::string imu = "gyro_x_dps,gyro_y_dps,gyro_z_dps,acc_x_g,acc_y_g,acc_z_g\n";
  for (int k = 0; k < 100 * 600; ++k) imu += fmt::format("{},0.002,0.003,0.0001,0.0002,-1\n", 0.001 * std::sin(k));
  write(dir, "imu.csv", imu);
  for (const auto& [command, name] : {std::pair<std::string, std::string>{"gap --records " + dir.str() + "/runs.csv", "gap.md"},
                                      {"noise --rate 100Hz --input " + dir.str() + "/imu.csv", "allan.svg"},
                                      {"gap-validate --quick", "validation.json"}}) {
    const fs::path out = dir.path() / ("out-" + name);
    fs::create_directories(out);
    fs::create_symlink("/etc/passwd", out / name);
    const ProgramResult r = run_limited(command + " --out " + out.string(), 10);  // refused at once, not after the work
    EXPECT_EQ(r.exit_code, 2) << command << "\n" << r.err;
    EXPECT_NE(r.err.find("is a symbolic link"), std::string::npos) << r.err;
  }
}

TEST(HostileFiles, InputsLargerOrLongerThanTheirBytesSuggestStayBounded) {
  TempDir dir;
  expect_refused("gap --records /dev/zero", "a record line may hold at most");
  expect_refused("compensate --records /dev/zero", "a record line may hold at most");
  // Five runs of 47 h of navigation, thinned to one r row every 10 min
  // (150 KB): the diagnosis's cost follows its rows, not the hours.
  std::string text = "# insmc-record v1\n# latitude_deg=45\n# system=1\n# test_duration_s=900\n# scheme=none\n"
                     "run,t_s,phase,f_x,f_y,f_z,r_x,r_y,r_z\n";
  for (int run = 0; run < 5; ++run) {
    for (int k = 1; k <= 90; ++k)
      text += fmt::format("{},{},test,{:.3g},{:.3g},{:.3g},{:.6g},{:.6g},{:.6g}\n", run, 10 * k, 1e-4 * std::sin(k + run),
                          1e-4 * std::cos(k), 1e-4 * std::sin(2 * k), 100 + std::sin(k), std::cos(k), std::sin(3 * k));
    for (double t = 1500; t < 47 * 3600; t += 600)
      text += fmt::format("{},{},nav,,,,{:.6g},{:.6g},{:.6g}\n", run, t, 1000 * std::sin(t / 800 + run),
                          500 * std::cos(t / 800), -t / 100);
  }
  // One effect at most: each greedy step adds a process's columns, and on
  // data this far outside the model the default three take about 70 s.
  const ProgramResult long_runs = run_limited(
      "gap --records " + write(dir, "long.csv", text) + " --format json --max-effects 1", kMaxSeconds);
  EXPECT_EQ(long_runs.exit_code, 0) << long_runs.err;
  EXPECT_LT(long_runs.peak_rss_kb, kMaxRssKb);
  // A million rows of one run: read into compact rows.
  {
    std::ofstream big(dir.path() / "big.csv");
    big << "# insmc-record v1\n# latitude_deg=45\n# system=1\n# test_duration_s=900\n# scheme=none\n"
           "run,t_s,phase,f_x,f_y,f_z,r_x,r_y,r_z\n";
    for (int k = 1; k <= 1000000; ++k)
      big << "0," << k * 0.1 << (k <= 9000 ? ",test," : ",nav,") << "1.5e-5,2.5e-5,-3.5e-5,12.5,23.5,34.5\n";
  }
  const ProgramResult big = run_limited("compensate --records " + dir.str() + "/big.csv --format csv", kMaxSeconds);
  EXPECT_LE(big.exit_code, 2) << big.err;
  EXPECT_LT(big.peak_rss_kb, kMaxRssKb);
  // The study's partial states: a default run in well under 1 GB.
  const ProgramResult study = run_limited("run --samples 2048 --quiet", kMaxSeconds);
  EXPECT_EQ(study.exit_code, 0) << study.err;
  EXPECT_LT(study.peak_rss_kb, kMaxRssKb / 2);
}

TEST(HostileFiles, ImportImuWritesOnlyFilesInsmcReads) {
  TempDir dir;
  std::string holed = "t,gyro_x_dps,gyro_y_dps,gyro_z_dps,acc_x_g,acc_y_g,acc_z_g\n";
  for (int k = 0; k < 100 * 600; ++k)
    holed += fmt::format("{},0.001,0.002,0.003,0.0001,0.0002,-1\n", 0.01 * k + (k > 30000 ? 100000.0 : 0.0));
  expect_refused("import-imu --input " + write(dir, "holed.csv", holed) + " --time-column t --latitude 51deg --out " +
                     dir.str() + "/h.rec --test-duration 2min --nav-duration 2min",
                 "a hole in the recording");
  std::string many = "gyro_x_dps,gyro_y_dps,gyro_z_dps,acc_x_g,acc_y_g,acc_z_g\n";
  for (int k = 0; k < 10 * 3600 * 8; ++k) many += "0.001,0.002,0.003,0.0001,0.0002,-1\n";
  expect_refused("import-imu --input " + write(dir, "many.csv", many) + " --rate 10Hz --latitude 51deg --out " +
                     dir.str() + "/m.rec --runs-from split --align-duration 10s --test-duration 1min "
                     "--nav-duration 1min --interval 1s --noise off",
                 "at most 200");
  EXPECT_FALSE(fs::exists(dir.path() / "h.rec"));
  EXPECT_FALSE(fs::exists(dir.path() / "m.rec"));
}

TEST(HostileFiles, AKilledPlottingProgramIsExitTwoAndWritesNothing) {
  TempDir dir;
  fs::create_directories(dir.path() / "bin");
  write(dir, "bin/gnuplot", "#!/bin/sh\nkill -9 $$\n");
  fs::permissions(dir.path() / "bin/gnuplot", fs::perms::owner_all);
  const ProgramResult r = run_limited("run --samples 2048 --quiet --out " + dir.str() + "/out", kMaxSeconds);
  EXPECT_EQ(r.exit_code, 0) << "the real gnuplot draws: " << r.err;
  const ProgramResult killed = run_shell("PATH=" + dir.str() + "/bin:$PATH " + insmc_path() +
                                         " run --samples 2048 --quiet --out " + dir.str() + "/killed");
  EXPECT_EQ(killed.exit_code, 2) << killed.err;
  EXPECT_NE(killed.err.find("gnuplot = killed by signal 9"), std::string::npos) << killed.err;
  EXPECT_FALSE(fs::exists(dir.path() / "killed"));
}

TEST(HostileFiles, AnAliasOfAnOutputSharesItsLock) {
  TempDir dir;
  fs::create_directories(dir.path() / "real");
  fs::create_symlink(dir.path() / "real", dir.path() / "alias");
  BackgroundProgram first(insmc_path() + " run --samples 1000000 --quiet --out " + dir.str() + "/real");
  // Until the first holds its lock (it takes it before any work).
  for (int i = 0; i < 200 && !fs::exists(dir.path() / ".real.insmc-lock"); ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(25));
  ASSERT_TRUE(fs::exists(dir.path() / ".real.insmc-lock")) << "the first run took no lock within 5 s";
  const ProgramResult second = run_insmc("run --samples 2048 --quiet --out " + dir.str() + "/alias");
  EXPECT_EQ(second.exit_code, 2) << second.err;
  EXPECT_NE(second.err.find("another insmc is writing this output now"), std::string::npos) << second.err;
  first.send(SIGKILL);
}

}  // namespace
}  // namespace insmc::testing
