#include "lib/compensation/truth_compensation.h"

#include "lib/common/assert.h"
#include "lib/compensation/schemes/scheme_definition.h"
#include "lib/preflight/instruments.h"
#include "lib/preflight/observables.h"

namespace insmc {

TestRunEstimates estimate_test_run(const TruthRun& run, const TestRunOptions& test,
                                   const TestRunEstimators& est, const ModelOptions& m) {
  const int K = test.intervals();
  INSMC_ASSERT(static_cast<int>(run.t_s.size()) == K + 1, "test run of {} samples for K = {}", run.t_s.size(), K);
  const double q = test.position_resolution_m;
  Eigen::MatrixXd pos_data(K, 3), accel_data(K, 3);
  const Vec3 true0 = true_position_ap(0.0, m);
  for (int a = 0; a < 3; ++a) {
    const PositionReadout readout(q, true0[a], true0[a] + run.position_error_ap_m[0][a]);
    for (int k = 1; k <= K; ++k) {
      const double truth = true_position_ap(run.t_s[k], m)[a];
      pos_data(k - 1, a) = readout.change_m(truth, truth + run.position_error_ap_m[k][a]);
      accel_data(k - 1, a) = run.accel_error_ap_mps2[k][a];
    }
  }
  const Eigen::Matrix<double, kEstimateRows, 3> u = apply_estimators<3>(est, m, test.duration_s, pos_data, accel_data);
  TestRunEstimates e;
  e.u2 = u.row(kU2Row).transpose();
  e.u3 = u.row(kU3Row).transpose();
  e.u3_accel = u.row(kU3AccelRow).transpose();
  e.df_at_test_end_mps2 = u.row(kDfAtTestEndRow).transpose();
  return e;
}

TruthSchemeSetup::TruthSchemeSetup(const TruthOptions& t, const TestRunOptions& r, const TestRunEstimators& e)
    : truth(t), test(r), estimators(e) {
  INSMC_ASSERT(!truth.accel_compensation.active() && truth.reset_at_s < 0 && !truth.torquer_command_radps,
               "the scheme sets the compensation itself");
}

namespace {

/// Offset of the noise streams of the navigation after a realignment.
constexpr std::uint64_t kRealignedNoiseStreams = 1u << 20;

std::vector<double> shifted(const std::vector<double>& times, double offset) {
  std::vector<double> out(times);
  for (double& t : out) t += offset;
  return out;
}

/// 5.4's alignment-phase measurements as counted, less what is known: the
/// torquer commands (5.14) in angle pulses, the accelerometer outputs (5.18)
/// in ΔV pulses, averaged over the last `alignment_average_s`.
/// What the alignment electronics saw (a run of the truth up to
/// switch-over: steady state, or the loops' averages over ta).
void alignment_measurements(const TruthSchemeSetup& s, const TruthSchemeSample& sample, const NormalSource& noise,
                            Vec3& commands_radps, Vec3& accel_mps2) {
  const ModelOptions& m = s.truth.model;
  const double w = m.earth_rate_radps, L = m.latitude_rad, ta = s.test.alignment_average_s;
  const Vec3 earth_rate_command(w * std::cos(L), 0.0, -w * std::sin(L));  // ω_in^n (2.6)
  TruthOptions o = s.truth;
  if (o.alignment_loops) o.alignment_loops->average_s = ta;
  const TruthRun aligned = simulate_truth(o, sample.x, {0.0}, noise);
  const Vec3 wc = aligned.alignment_command_radps, df = aligned.alignment_accel_output_mps2;
  for (int a = 0; a < 3; ++a) {
    commands_radps[a] = counted_mean(wc[a], earth_rate_command[a], ta, s.test.torquer_pulse_rad, sample.torquer_phase01[a]);
    accel_mps2[a] = counted_mean(df[a], a == 2 ? -m.gravity_mps2 : 0.0, ta, s.test.dv_pulse_mps, sample.align_pulse_phase01[a]);
  }
}

}  // namespace

TruthRun run_truth_test(const TruthSchemeSetup& s, const TruthSchemeSample& sample, const NormalSource& noise) {
  TruthOptions o = s.truth;
  o.pulse_phase = sample.pulse_phase;
  return simulate_truth(o, sample.x, uniform_times(s.test.duration_s, s.test.filter_interval_s), noise);
}

TruthSchemeRun run_truth_scheme(Scheme scheme, const TruthSchemeSetup& s, const TruthSchemeSample& sample,
                                const std::vector<double>& clock_times_s, const NormalSource& noise,
                                const TruthRun* test_run) {
  const ModelOptions& m = s.truth.model;
  const double T = s.test.duration_s;
  const SchemeDefinition& definition = scheme.definition();
  TruthOptions o = s.truth;
  o.pulse_phase = sample.pulse_phase;
  TruthSchemeRun run;
  if (uses_test_run(scheme)) {
    run.test = test_run != nullptr ? *test_run : run_truth_test(s, sample, noise);
    run.estimates = estimate_test_run(run.test, s.test, s.estimators, m);
  }
  const TestRunEstimates& e = run.estimates;
  AccelCompensation& c = o.accel_compensation;
  UncertaintyVector x = realigns(scheme) ? sample.realigned_x : sample.x;
  // A realignment starts from the navigating platform, level and in azimuth
  // to within the test run's drift angles (a fraction of a mrad), not from a
  // coarse alignment: its loops are taken in steady state. The second
  // navigation has its own pulse phase and effect processes.
  NormalSource flight_noise = noise;
  if (realigns(scheme)) {
    o.alignment_loops.reset();
    o.pulse_phase = sample.align_pulse_phase01 - Vec3::Constant(0.5);
    x[uncertainty_slot::kTheodolite] += x[uncertainty_slot::kRealignAzimuthError];  // the theodolite re-sighted: (u)ψ + δψ_r
    if (noise) flight_noise = [noise](std::uint64_t stream, std::uint64_t counter) {
      return noise(stream + kRealignedNoiseStreams, counter);
    };
  }
  TruthSchemeContext context{s.truth.system, m, T, e};
  if (definition.uses_alignment_data)
    alignment_measurements(s, sample, noise, context.alignment_commands_radps, context.alignment_accel_mps2);
  if (definition.resets_at_test_end) {  // points 5, 6 at T; the compensation acts from T
    c.start_s = T;
    o.reset_at_s = T;
  }
  definition.truth_action(context, o, x);
  const double offset = frame_time_offset_s(scheme, T);
  run.flight = simulate_truth(o, x, shifted(clock_times_s, offset), flight_noise);
  return run;
}

}  // namespace insmc
