#pragma once
/// The compensation schemes of chapter 5 acting on the truth simulator
/// (each scheme's own action: schemes/, its truth_action)
/// (docs/truth-vs-models.md) through the same injection points of fig. 5.1 as
/// compensation_maps.h uses on the linear model:
///   * the test run is a truth run; its data are what the instruments give
///     (ΔV pulses through the filter box, the position computer at its
///     resolution), and the least-squares estimators of (4.4), (4.8) turn
///     them into Û2, Û3 and Δf̂(T) (5.10);
///   * point 2 and the integrators into it: TruthOptions::accel_compensation;
///   * point 4: the torquer command hook (5.4: the measured alignment
///     commands (5.15), (5.16)); for 5.1.2 and `combined` the torquer rates
///     ω_cp (5.5) act through the realignment and after it, i.e. on the
///     platform like a change of the level-platform drift ω_do;
///   * points 5, 6: TruthOptions::reset_at_s (5.2, 5.3 at T);
///   * a realignment: a new truth run whose per-alignment uncertainties (ζ_r,
///     ∂f_r, (u)V) are the fresh draws, switched over at the scheme's t = 0.
/// The alignment-phase measurements of 5.4 are what the truth's alignment
/// electronics saw (TruthRun::alignment_command_radps, with the effects'
/// alignment-phase terms), counted in pulses. After a realignment the
/// effects' processes and the pulse phase are drawn afresh (their own noise
/// streams), not a replay of the test run's.
#include <vector>

#include "lib/compensation/scheme.h"
#include "lib/preflight/test_run_estimates.h"
#include "lib/preflight/test_run.h"
#include "lib/truth/simulator.h"

namespace insmc {

/// Estimates from a test run sampled at t_k = kτ, k = 0..K (uniform_times(T, τ)):
/// Δf^a per filter interval as recorded, Δr_k from the position error at the
/// computer's resolution (its phase set by the true position of the vehicle).
TestRunEstimates estimate_test_run(const TruthRun& test_run, const TestRunOptions& test,
                                   const TestRunEstimators& estimators, const ModelOptions& model);

/// Everything of a truth study fixed across samples.
struct TruthSchemeSetup {
  TruthSchemeSetup(const TruthOptions& truth, const TestRunOptions& test, const TestRunEstimators& estimators);
  TruthOptions truth;  ///< site, system, pulses, effects (no compensation of its own)
  TestRunOptions test;
  TestRunEstimators estimators;
};

/// One sample's draws.
struct TruthSchemeSample {
  UncertaintyVector x;           ///< the uncertainties
  UncertaintyVector realigned_x; ///< x with a realignment's fresh draws (realigning schemes)
  Vec3 pulse_phase = Vec3::Zero();  ///< ΔV remainders at switch-over, in pulses [−0.5, 0.5)
  Vec3 torquer_phase01 = Vec3::Zero();    ///< 5.4: torquer pulse counters' phases [0, 1)
  /// 5.4: alignment ΔV counters' phases [0, 1); after a realignment (no 5.4
  /// measurement) the phases of the second navigation's counters.
  Vec3 align_pulse_phase01 = Vec3::Zero();
};

/// A compensated truth run.
struct TruthSchemeRun {
  TruthRun test;  ///< the test run at t_k = kτ (empty for none and 5.4)
  TestRunEstimates estimates;
  /// The run after the scheme at the requested clock times (clock_of): its
  /// t_s are on the simulator's time since the switch-over that started it
  /// (T + t' for 5.2, 5.3; t for the others).
  TruthRun flight;
};

/// `test_run`: the sample's test run if already simulated (the same for
/// every scheme that uses one: run_truth_test); else it is simulated here.
TruthSchemeRun run_truth_scheme(Scheme scheme, const TruthSchemeSetup& setup, const TruthSchemeSample& sample,
                                const std::vector<double>& clock_times_s, const NormalSource& noise = {},
                                const TruthRun* test_run = nullptr);

/// The sample's test run at t_k = kτ, k = 0..K, before any compensation.
TruthRun run_truth_test(const TruthSchemeSetup& setup, const TruthSchemeSample& sample, const NormalSource& noise = {});

}  // namespace insmc
