// The pulse weight of f read from the rows (record_lattice.h): counters of
// weight w in a world whose specific force is the site's g_s, not the
// nominal's g (the truth simulator's, docs/truth-vs-models.md: 0.17 % less
// at 45°), with filter windows of 10 s and of 20 s, and continuous outputs;
// the resolution of r as another writer prints it (9 significant digits,
// millimetres).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "lib/preflight/test_run.h"
#include "montecarlo/records/runs/files/layout.h"
#include "montecarlo/records/runs/files/record_lattice.h"

namespace insmc::runs {
namespace {

constexpr double kPulse = 0.1 * 0.3048;

/// One run of T = 900 s whose f rows are what counters of weight `pulse`
/// (0: continuous) give over windows of tau: the counted velocity
/// w round(ρ0 + V/w) of V = (g_s/g) × nominal + a bias ramp, less the
/// recorder's nominal increment (at g_s), over τ.
RecordFile counted_records(double tau, double pulse) {
  const ModelOptions model;
  const double scale = 1 - 0.0017;  // g_s / g
  const Vec3 bias(2e-3, -1.5e-3, 1e-3);
  const Vec3 phase(0.3, -0.2, 0.1);
  RecordFile f;
  f.header = RecordHeader::make(45.0, System::kTheodolite, 900.0, Scheme::kNone);
  RecordRun run;
  run.id = 1;
  const auto counted = [&](double t) {
    Vec3 v = scale * nominal_velocity_increment(t, model) + bias * t;
    if (pulse > 0)
      for (int a = 0; a < 3; ++a) v[a] = pulse * std::round(phase[a] + v[a] / pulse);
    return v;
  };
  for (double t = tau; t <= 900.0 + 1e-9; t += tau) {
    RecordRow row;
    row.run = 1;
    row.t_s = t;
    row.phase = Phase::kTest;
    // The recorder takes off its own nominal, at the site's g_s; the
    // reader adds back the report's (at g).
    const Vec3 f = (counted(t) - counted(t - tau) -
                    scale * (nominal_velocity_increment(t, model) - nominal_velocity_increment(t - tau, model))) / tau;
    for (int a = 0; a < 3; ++a) row.f_mps2[static_cast<std::size_t>(a)] = f[a];
    row.r_ap_m = Vec3::Zero();
    run.rows.push_back(row);
  }
  f.runs.push_back(run);
  return f;
}

TEST(RecordLattice, PulsesAreFoundInWindowsOfTenAndOfTwentySeconds) {
  for (const double tau : {10.0, 20.0, 30.0}) {
    const LatticeFit fit = f_pulse_lattice(counted_records(tau, kPulse), ModelOptions{}, tau);
    EXPECT_EQ(fit.kind, LatticeFit::Kind::kLattice) << "tau " << tau;
    EXPECT_NEAR(fit.step, kPulse, 0.01 * kPulse) << "tau " << tau;
  }
}

TEST(RecordLattice, PulsesAreFoundWhenTheLoggerDroppedRecords) {
  // A logger that lost a few windows' records (a different one in each
  // stretch): the differences are taken within stretches of consecutive
  // windows only. Across a dropped window the nominal's leftover (g_s
  // against g) no longer cancels; at τ = 39 s one such difference put the
  // whole file off the lattice (continuous outputs assumed, and a unit's
  // counted rows then misfit its model by a chi-square of millions).
  for (const double tau : {10.0, 30.0, 39.0}) {
    RecordFile file = counted_records(tau, kPulse);
    std::vector<RecordRow>& rows = file.runs[0].rows;
    for (const std::size_t k : {16u, 9u, 4u}) rows.erase(rows.begin() + static_cast<std::ptrdiff_t>(k));
    const LatticeFit fit = f_pulse_lattice(file, ModelOptions{}, tau);
    EXPECT_EQ(fit.kind, LatticeFit::Kind::kLattice) << "tau " << tau;
    EXPECT_NEAR(fit.step, kPulse, 0.01 * kPulse) << "tau " << tau;
  }
}

/// Stamps that jitter about the windows' grid by up to `share` of τ (the
/// windows themselves stay the grid's), in a fixed pattern over ±share.
void jitter_stamps(RecordFile& file, double tau, double share) {
  int i = 0;
  for (RecordRun& run : file.runs)
    for (RecordRow& row : run.rows) row.t_s += share * tau * std::sin(2.4 * ++i);
}

TEST(RecordLattice, PulsesAreFoundWhenTheStampsJitter) {
  // A logger whose stamps jitter 0.9 % of τ about the grid: the nominal's
  // increment taken at the stamp turns with the earth by ω_ie g τ per
  // second of jitter, 1 % of a 0.1 ft/s pulse at 50 ms on 10 s, and hid
  // the pulses (continuous outputs assumed, the pulse noise then missed).
  for (const double tau : {10.0, 20.0}) {
    RecordFile file = counted_records(tau, kPulse);
    jitter_stamps(file, tau, 0.009);
    const LatticeFit fit = f_pulse_lattice(file, ModelOptions{}, tau);
    EXPECT_EQ(fit.kind, LatticeFit::Kind::kLattice) << "tau " << tau;
    EXPECT_NEAR(fit.step, kPulse, 0.01 * kPulse) << "tau " << tau;
  }
}

TEST(RecordLattice, TheFilterIntervalOfStampsThatJitterIsTheGridsInItsFewDigits) {
  // Twenty runs of 90 windows, each run missing a few: the median spacing
  // of jittered stamps is one stamp's jitter off τ, and windows counted
  // from it drift off the rows within the test run.
  for (const double tau : {10.0, 0.5, 0.015625}) {
    RecordFile file;
    file.header = RecordHeader::make(45.0, System::kTheodolite, 90 * tau, Scheme::kNone);
    for (int id = 1; id <= 20; ++id) {
      RecordRun run;
      run.id = id;
      for (int k = 1; k <= 90; ++k) {
        if ((k * 7 + id) % 23 == 0) continue;  // a dropped record
        RecordRow row;
        row.run = id;
        row.t_s = k * tau;
        row.phase = Phase::kTest;
        row.f_mps2 = {1e-4, 2e-4, 3e-4};
        run.rows.push_back(row);
      }
      file.runs.push_back(run);
    }
    EXPECT_DOUBLE_EQ(median_f_spacing(file), tau) << "exact stamps, tau " << tau;
    jitter_stamps(file, tau, 0.005);
    std::vector<double> spacings;
    for (const RecordRun& run : file.runs)
      for (std::size_t i = 1; i < run.rows.size(); ++i) spacings.push_back(run.rows[i].t_s - run.rows[i - 1].t_s);
    std::nth_element(spacings.begin(), spacings.begin() + static_cast<std::ptrdiff_t>(spacings.size() / 2),
                     spacings.end());
    EXPECT_NE(spacings[spacings.size() / 2], tau) << "the raw median is off τ (else this test shows nothing)";
    EXPECT_DOUBLE_EQ(median_f_spacing(file), tau) << "jittered stamps, tau " << tau;
  }
}

TEST(RecordLattice, ContinuousOutputsLieOnNoLattice) {
  for (const double tau : {10.0, 20.0}) {
    const LatticeFit fit = f_pulse_lattice(counted_records(tau, 0.0), ModelOptions{}, tau);
    EXPECT_EQ(fit.kind, LatticeFit::Kind::kContinuous) << "tau " << tau;
  }
}

/// One run's test-run r rows of a position computer of resolution `q` (0:
/// exact) reading out the true position plus a drifting error, r = readout −
/// true position, printed with printf format `format`.
RecordFile readout_records(double q, const char* format) {
  const ModelOptions model;
  RecordFile f;
  f.header = RecordHeader::make(45.0, System::kTheodolite, 900.0, Scheme::kNone);
  RecordRun run;
  run.id = 1;
  for (double t = 10.0; t <= 900.0 + 1e-9; t += 10.0) {
    const Vec3 truth = true_position_ap(t, model);
    const Vec3 error(40.0 + 0.3 * t, -25.0 + 1e-4 * t * t, 12.0 - 0.05 * t);
    RecordRow row;
    row.run = 1;
    row.t_s = t;
    row.phase = Phase::kTest;
    Vec3 r;
    for (int a = 0; a < 3; ++a) {
      const double read = q > 0 ? q * std::round((truth[a] + error[a]) / q) : truth[a] + error[a];
      char text[64];
      std::snprintf(text, sizeof text, format, read - truth[a]);
      r[a] = std::stod(text);
    }
    row.r_ap_m = r;
    run.rows.push_back(row);
  }
  f.runs.push_back(run);
  return f;
}

TEST(RecordLattice, AResolutionIsFoundInRowsPrintedToFewDigits) {
  constexpr double kResolution = 3 * 0.3048;
  for (const char* format : {"%.17g", "%.9g", "%.3f"}) {
    const LatticeFit fit = r_resolution_lattice(readout_records(kResolution, format), ModelOptions{});
    EXPECT_EQ(fit.kind, LatticeFit::Kind::kLattice) << format;
    EXPECT_NEAR(fit.step, kResolution, 0.01 * kResolution) << format;
  }
  for (const char* format : {"%.17g", "%.9g"})
    EXPECT_EQ(r_resolution_lattice(readout_records(0.0, format), ModelOptions{}).kind, LatticeFit::Kind::kContinuous)
        << format;
}

}  // namespace
}  // namespace insmc::runs
