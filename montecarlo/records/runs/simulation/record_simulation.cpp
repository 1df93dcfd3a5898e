#include "montecarlo/records/runs/simulation/record_simulation.h"

#include <fmt/format.h>

#include <cmath>

#include "lib/common/assert.h"
#include "lib/truth/effect.h"
#include "lib/units/units.h"
#include "lib/preflight/instruments.h"
#include "lib/preflight/test_run.h"
#include "montecarlo/study/random/philox.h"
#include "montecarlo/study/sampler/truth_sample.h"

namespace insmc::runs {

NormalSource philox_normals(std::uint64_t seed, std::uint64_t run) {
  return [seed, run](std::uint64_t stream, std::uint64_t counter) {
    const mc::PhiloxBlock ctr = {static_cast<std::uint32_t>(run), static_cast<std::uint32_t>(run >> 32),
                             static_cast<std::uint32_t>(mc::Stream::TruthEffects) + 0x100u * static_cast<std::uint32_t>(stream + 1),
                             static_cast<std::uint32_t>(counter)};
    INSMC_ASSERT(counter < (1ull << 32) && stream < (1ull << 23), "noise draw {} of stream {}", counter, stream);
    const mc::PhiloxBlock out = mc::philox4x32_10(ctr, mc::philox_key(seed));
    return mc::inverse_normal_cdf(mc::open_uniform01_from_words(out[0], out[1]));
  };
}

namespace {

/// A record row from one output of a truth run. r is what the position
/// computer reads out at its resolution, less the true position: the
/// rounding acts on the position (its phase set by where the vehicle is),
/// as in the test-run pipeline, not on the error.
RecordRow record_row(std::int64_t run, double t_s, const TruthRun& r, std::size_t k, const RecordRunSpec& spec,
                     const ModelOptions& model) {
  // The vehicle's position at the simulator's own time (after a realignment
  // the second navigation's clock, not the record's).
  const double truth_t_s = r.t_s[k];
  RecordRow row;
  row.run = run;
  row.t_s = t_s;
  row.phase = t_s <= spec.test_duration_s + 1e-9 ? Phase::kTest : Phase::kNav;
  for (int a = 0; a < 3; ++a)
    if (std::isfinite(r.accel_error_ap_mps2[k][a])) row.f_mps2[a] = r.accel_error_ap_mps2[k][a];
  Vec3 pos = r.position_error_ap_m[k];
  if (spec.position_resolution_m > 0) {
    const Vec3 truth = true_position_ap(truth_t_s, model);
    for (int a = 0; a < 3; ++a) pos[a] = position_reading_error(truth[a], truth[a] + pos[a], spec.position_resolution_m);
  }
  row.r_ap_m = pos;
  return row;
}

/// A run after spec.scheme: test rows from the scheme's test run, nav rows
/// from the run after the scheme, on the record's clock.
RecordRun scheme_record_run(const mc::Sampler& sampler, std::uint64_t seed, std::uint64_t run,
                            const std::vector<double>& times_s, const RecordRunSpec& spec) {
  INSMC_ASSERT(spec.setup != nullptr, "a scheme record needs its setup");
  const TruthSchemeSample sample = mc::draw_truth_sample(sampler, seed, run, sampler.draw(seed, run));
  const double T = spec.test_duration_s;
  const double clock_zero = clock_start_s(spec.scheme, T, spec.nav_start_s);
  std::vector<double> clock;
  for (double t : times_s)
    if (t > T + 1e-9 || !uses_test_run(spec.scheme)) clock.push_back(t - clock_zero);
  INSMC_ASSERT(clock.empty() || clock.front() >= -1e-9, "nav row at {} s before the scheme's t = 0", clock.front() + clock_zero);
  for (double& t : clock) t = std::max(t, 0.0);
  const TruthSchemeRun r = run_truth_scheme(spec.scheme, *spec.setup, sample, clock, philox_normals(seed, run));
  RecordRun out;
  out.id = static_cast<std::int64_t>(run);
  std::size_t test_k = 1, nav_k = 0;
  for (double t : times_s) {
    if (t <= T + 1e-9 && uses_test_run(spec.scheme)) {
      INSMC_ASSERT(test_k < r.test.t_s.size() && std::abs(r.test.t_s[test_k] - t) < 1e-6,
                   "test rows must be the filter grid: {} s", t);
      out.rows.push_back(record_row(out.id, t, r.test, test_k++, spec, spec.setup->truth.model));
    } else {
      out.rows.push_back(record_row(out.id, t, r.flight, nav_k++, spec, spec.setup->truth.model));
    }
  }
  return out;
}

}  // namespace

RecordRun simulate_record_run(const TruthOptions& truth, const mc::Sampler& sampler, std::uint64_t seed,
                              std::uint64_t run, const std::vector<double>& times_s,
                              const RecordRunSpec& spec) {
  if (spec.scheme != Scheme::kNone) return scheme_record_run(sampler, seed, run, times_s, spec);
  TruthOptions o = truth;
  const TruthSchemeSample sample = mc::draw_truth_sample(sampler, seed, run, sampler.draw(seed, run));
  o.pulse_phase = sample.pulse_phase;
  const TruthRun r = simulate_truth(o, sample.x, times_s, philox_normals(seed, run));
  RecordRun out;
  out.id = static_cast<std::int64_t>(run);
  for (std::size_t k = 0; k < r.t_s.size(); ++k) out.rows.push_back(record_row(out.id, r.t_s[k], r, k, spec, truth.model));
  return out;
}

RecordRun simulate_like(const RecordRun& pattern, const TruthOptions& truth, const mc::Sampler& sampler,
                        std::uint64_t seed, std::uint64_t run, const RecordRunSpec& spec) {
  std::vector<const RecordRow*> rows;
  std::vector<double> times;
  for (const RecordRow& row : pattern.rows)
    if (row.phase != Phase::kAlign) rows.push_back(&row), times.push_back(row.t_s);
  RecordRun out = simulate_record_run(truth, sampler, seed, run, times, spec);
  for (std::size_t k = 0; k < out.rows.size(); ++k) {
    out.rows[k].phase = rows[k]->phase;
    for (int a = 0; a < 3; ++a)
      if (!rows[k]->f_mps2[a]) out.rows[k].f_mps2[a].reset();
  }
  return out;
}

RecordFile simulate_own_file(const TruthOptions& truth, const mc::Sampler& sampler, std::uint64_t seed,
                             const OwnFileSpec& spec) {
  const double T = spec.test_duration_s, tau = truth.filter_interval_s;
  // After a realignment the second navigation starts at nav_start_s = T + the
  // realignment; its rows follow on the same filter grid.
  const bool second_switch = realigns(spec.scheme);
  const double nav_start_s = second_switch ? ready_time_s(spec.scheme, T, spec.realignment_duration_s) : T;
  std::vector<double> times = uniform_times(T, tau, false);
  for (double t : uniform_times(spec.nav_duration_s, tau, false)) times.push_back(nav_start_s + t);
  RecordFile file;
  file.header = RecordHeader::make(truth.model.latitude_rad / kDegToRad, truth.system, T, spec.scheme);
  file.header.set("dv_pulse_mps", truth.dv_pulse_mps);
  if (spec.position_resolution_m) file.header.set("position_resolution_m", *spec.position_resolution_m);
  file.header.set("filter_interval_s", tau);
  if (second_switch) file.header.set("nav_start_s", nav_start_s);
  file.header.set("truth.seed", static_cast<double>(seed));
  for (std::size_t i = 0; i < truth.effects.size(); ++i)
    file.header.set(fmt::format("truth.effect.{}", i), format_effect(truth.effects[i]));
  const RecordRunSpec run_spec{T, spec.position_resolution_m.value_or(0.0), spec.scheme, spec.setup, nav_start_s};
  for (int run = 0; run < spec.runs; ++run)
    file.runs.push_back(simulate_record_run(truth, sampler, seed, static_cast<std::uint64_t>(run), times, run_spec));
  return file;
}

}  // namespace insmc::runs
