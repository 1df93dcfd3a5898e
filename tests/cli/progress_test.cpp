// Progress for the commands that take longer than a second or two: rank's
// break-even searches, a sweep's points, noise's channels. On a terminal
// (stderr a tty: run under script(1)) after a second; in a log with
// INSMC_PROGRESS=always (which these short studies use, being faster than
// the second a terminal waits); in a pipe, none.
#include <gtest/gtest.h>

#include <cmath>
#include <fmt/format.h>
#include <fstream>
#include <random>
#include <string>

#include "tests/cli/run_program.h"
#include "tests/ordered_draws.h"

namespace insmc::testing {
namespace {

/// insmc with `args` under a pseudo-terminal: what the terminal showed.
ProgramResult on_a_terminal(const std::string& args) {
  return run_shell(fmt::format("script -qec '{} {}' /dev/null", insmc_path(), args));
}

/// insmc with `args` and INSMC_PROGRESS=always, stderr a pipe.
ProgramResult with_progress(const std::string& args) {
  return run_shell(fmt::format("INSMC_PROGRESS=always {} {}", insmc_path(), args));
}

TEST(Progress, RankShowsItsBreakEvenSearches) {
  const ProgramResult r = with_progress("rank --samples 1000 --system 1 --scheme 5.1.2,5.4 --quiet");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(has(r.err, "Monte Carlo study: ")) << r.err;
  EXPECT_TRUE(has(r.err, "break-even searches: ")) << r.err;
  EXPECT_TRUE(has(r.err, " study maps, ")) << r.err;
  EXPECT_EQ(r.out, "");
  // In a pipe (scripts, CI) nothing but the result.
  const ProgramResult piped = run_insmc("rank --samples 1000 --system 1 --scheme 5.1.2,5.4 --quiet");
  ASSERT_EQ(piped.exit_code, 0) << piped.err;
  EXPECT_EQ(piped.err, "");
}

TEST(Progress, ASweepCountsItsPoints) {
  const ProgramResult r =
      with_progress("run --samples 2000 --scheme none --system 1 --test-duration 5min,10min,15min --quiet");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(has(r.err, "sweep: 3 / 3 points")) << r.err;
  const ProgramResult never = run_shell(fmt::format(
      "INSMC_PROGRESS=never script -qec '{} run --samples 2000 --test-duration 5min,10min --quiet' /dev/null",
      insmc_path()));
  ASSERT_EQ(never.exit_code, 0) << never.err;
  EXPECT_EQ(never.out, "") << "never: silent on a terminal too";
}

TEST(Progress, NoiseNamesItsStagesOnATerminal) {
  TempDir dir;
  const std::string input = (dir.path() / "imu.csv").string();
  {
    std::ofstream f(input);
    f << "gyro_x_dps,gyro_y_dps,gyro_z_dps,acc_x_g,acc_y_g,acc_z_g\n";
    std::mt19937_64 rng(5);
    std::normal_distribution<double> e(0.0, 1.0);
    for (int k = 0; k < 400000; ++k) {
      const auto z = ordered_draws<6>(e, rng);
      f << fmt::format("{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g}\n", 0.01 * z[0], 0.01 * z[1], 0.01 * z[2],
                       1e-4 * z[3], 1e-4 * z[4], -1 + 1e-4 * z[5]);
    }
  }
  const ProgramResult r = on_a_terminal("noise --input " + input + " --rate 100Hz --format json");
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_TRUE(has(r.out, "Allan deviation and fit per channel: ")) << r.out.substr(0, 400);
}

}  // namespace
}  // namespace insmc::testing
