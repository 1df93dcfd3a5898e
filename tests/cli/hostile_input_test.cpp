// Hostile input, end to end: huge, tiny and non-finite values, oversized
// lists and inputs that once aborted, hung or exhausted memory. Each case
// must end with exit 0, 1 or 2 (never a signal, never exit 3) within its
// time limit and under a 4 GB address-space limit, and a refusal is one
// line on stderr naming what was refused.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <string>

#include "tests/cli/run_program.h"

namespace insmc::testing {
namespace {

int line_count(const std::string& s) { return static_cast<int>(std::count(s.begin(), s.end(), '\n')); }

/// Runs insmc under `timeout` (and a 4 GB address-space limit) so that a
/// hang or runaway allocation fails the test instead of the whole suite.
ProgramResult run_bounded(const std::string& args, int seconds = 120) { return run_limited(args, seconds, true); }

struct Refusal {
  std::string args;
  std::string names;  // text the one-line message must contain
};

void expect_refused(const Refusal& c) {
  const ProgramResult r = run_bounded(c.args);
  EXPECT_EQ(r.exit_code, 2) << c.args << "\n" << r.err;
  EXPECT_EQ(line_count(r.err), 1) << c.args << "\n" << r.err;
  EXPECT_NE(r.err.find(c.names), std::string::npos) << c.args << "\n" << r.err;
}

std::string comma_list(int n, const std::string& unit) {
  std::string out;
  for (int i = 1; i <= n; ++i) out += (i > 1 ? "," : "") + std::to_string(i) + unit;
  return out;
}

TEST(HostileInput, HugeAndTinyValuesAreRefusedBeforeAnyWork) {
  TempDir dir;
  const std::string rec = " --out " + dir.str() + "/x.rec";
  const Refusal cases[] = {
      {"run --bound gyro_drift=1e15meru", "gyro_drift_x"},
      {"run --bound gyro_drift=1e300meru --samples 2000", "gyro_drift_x"},
      {"run --bound altitude_error=1e9m", "altitude_error"},
      {"run --dist gyro_drift=fixed:1e300meru", "gyro_drift_x"},
      {"run --dist accel_bias=normal:1e-300", "accel_bias_x"},
      {"run --leveling-gain 1e-300", "--leveling-gain"},
      {"run --leveling-gain 1e300", "--leveling-gain"},
      {"run --dv-pulse 1e300mps", "--dv-pulse"},
      {"run --sway 1e300mps,1e-300s", "--sway"},
      {"run --sway 5mmps,1e-300s", "--sway time"},
      {"run --torquer-pulse 1e300rad", "--torquer-pulse"},
      {"run --filter-interval 1e-6s", "--filter-interval"},
      {"run --filter-interval 0.1s --test-duration 2h", "--filter-interval"},
      {"run --position-resolution 1e300m", "--position-resolution"},
      {"run --realignment-duration 1e300s", "--realignment-duration"},
      {"run --alignment-average 1e300s", "--alignment-average"},
      {"run --samples 18446744073709551615", "--samples"},
      {"run --threads 1000000", "--threads"},
      {"run --confidence 0.9999999999999999", "0.9999999999999999"},
      {"run --checkpoint-every 1e-300s --checkpoint " + dir.str() + "/c.ck", "--checkpoint-every"},
      {"run --fidelity truth --alignment-time 1e300s", "--alignment-time"},
      {"run --fidelity truth --alignment-time 10min --coarse-misalignment 1rad,0rad,0rad", "--coarse-misalignment"},
      {"covariance --bound gyro_drift=1e15meru", "gyro_drift_x"},
      {"covariance --dv-pulse 1e300mps", "--dv-pulse"},
      {"covariance --fidelity truth", "--fidelity"},
      {"covariance --confidence 0.9", "--confidence"},
      {"covariance --alignment-time 10min", "--alignment-time"},
      {"run --samples 1e300", "--samples"},
      {"run --samples 2.5", "--samples"},
      {"run --samples -1e3", "--samples"},
      {"simulate --bound gyro_drift=1e300meru" + rec, "gyro_drift_x"},
      {"simulate --effect accel_bias_instability:sigma=1e300mps2,tau=600s" + rec, "accel_bias_instability.sigma"},
      {"simulate --effect sway:accel_rms=1e300mps2" + rec, "sway.accel_rms"},
      {"simulate --effect gyro_drift_instability:tau=1e300s" + rec, "gyro_drift_instability.tau"},
      {"simulate --step 1e-300s" + rec, "step"},
      {"simulate --runs 1000000000" + rec, "--runs"},
      // one more than gap diagnoses at once: the file would be refused by its reader
      {"simulate --runs 201" + rec, "--runs"},
      // a realignment of no duration: the records' navigation would start at the test's end
      {"simulate --system 2 --scheme 5.1.1 --realignment-duration 1e-300s" + rec, "--realignment-duration"},
      {"bench --samples 18446744073709551615", "--samples"},
      {"bench --threads 100000", "--threads"},
      {"gap-validate --quick --effect sway --magnitudes 1000", "sway.accel_rms"},
  };
  for (const Refusal& c : cases) expect_refused(c);
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "x.rec"));
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "c.ck"));
}

TEST(HostileInput, OversizedSweepsAreRefusedBeforeTheFirstPoint) {
  const Refusal cases[] = {
      {"run --test-duration " + comma_list(3000, "min"), "at most 100 values"},
      {"run --samples 2000 --test-duration " + comma_list(40, "min") + " --dv-pulse " + comma_list(40, "mmps"),
       "points"},
      // The last point is out of range: refused before the first is computed.
      {"run --samples 100000000 --test-duration 5min,10min,3h", "--test-duration"},
      {"run --samples 100000000 --bound gyro_drift=1meru,1e9meru", "gyro_drift_x"},
  };
  for (const Refusal& c : cases) expect_refused(c);
}

TEST(HostileInput, ValuesAtTheEdgesOfTheirRangesRun) {
  // The largest and smallest values allowed are computed, not refused.
  for (const std::string args : {
           "run --samples 2048 --bound gyro_drift=10000meru --scheme none,5.2",
           "run --samples 2048 --dist all=zero --leveling-gain 10 --scheme none",
           "run --samples 2048 --dv-pulse 1mps --position-resolution 1km --scheme 5.2,5.3",
           "run --samples 2048 --filter-interval 4s --test-duration 2h --system 1 --scheme none,5.3",
           "run --samples 2048 --confidence 0.999999 --scheme none",
           "covariance --bound accel_bias=100mg",
       }) {
    const ProgramResult r = run_bounded(args + " --format csv", 300);
    EXPECT_EQ(r.exit_code, 0) << args << "\n" << r.err;
    EXPECT_EQ(r.out.find("nan"), std::string::npos) << args;
  }
}

TEST(HostileInput, TruthSimulationWithTinyPulsesAndHugeDriftEnds) {
  // Pulse weights far below the signal (many crossings per step) and the
  // largest drift allowed: the remainder integral takes its dense path.
  TempDir dir;
  for (const std::string args : {
           "simulate --runs 1 --nav-duration 10min --effect quantization:dv_pulse=1e-9mps",
           "simulate --runs 1 --nav-duration 10min --bound gyro_drift=10000meru --dist gyro_drift=fixed:10000meru",
       }) {
    const ProgramResult r = run_bounded(args + " --out " + dir.str() + "/t.rec", 300);
    EXPECT_EQ(r.exit_code, 0) << args << "\n" << r.err;
  }
}

}  // namespace
}  // namespace insmc::testing
