// The gap diagnosis' linear-Gaussian run model (montecarlo/gap/model): responses against
// closed forms and against the linear model's own columns, the analyser's
// expected squares against draws from the model, the metric, the candidates
// and the extraction of records other software may write.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <tuple>

#include "lib/truth/simulator.h"
#include "lib/uncertainty/uncertainty_model.h"
#include "lib/units/units.h"
#include "montecarlo/gap/candidates/candidates.h"
#include "montecarlo/gap/metric/gap_metric.h"
#include "montecarlo/gap/model/gaussian_model.h"
#include "montecarlo/gap/model/pulse_counting.h"
#include "montecarlo/gap/model/response.h"
#include "montecarlo/gap/model/run_analysis.h"
#include "tests/unit/montecarlo/gap/test_layout.h"

namespace insmc::gap {
namespace {

RecordSite site() {
  RecordSite s;
  s.filter_interval_s = 10.0;
  s.dv_pulse_mps = 0.1 * kFtpsToMps;
  return s;
}

Layout layout(double end_s) { return testing::test_layout(end_s); }

TEST(GapResponse, ConstantAccelerometerErrorGivesTheSchulerClosedForm) {
  const Layout l = layout(3000.0);
  const RecordSite s = site();
  InputSignal in;
  in.columns = 1;
  in.at = [](double, Columns3& a, Columns3& th) {
    a.setZero();
    th.setZero();
    a(0, 0) = 1.0;
  };
  const Eigen::MatrixXd r = input_response(l, s, in);
  const double ws = s.model.schuler_radps();
  for (std::size_t i = 0; i < l.rows.size(); ++i) {
    const ObservationRow& row = l.rows[i];
    const double want = row.axis != 0 ? 0.0
                        : row.quantity == Quantity::kF ? 1.0
                                                       : (1.0 - std::cos(ws * row.t_s)) / (ws * ws);  // (3.24)
    EXPECT_NEAR(r(static_cast<Eigen::Index>(i), 0), want, 1e-9 * (1.0 + std::abs(want))) << row.t_s;
  }
}

TEST(GapResponse, AnAccelerometerInputEqualsTheLinearModelsSwitchOverBiasColumn) {
  // ∂f_cx enters the linear model (3.18) as a pure navigation-mode bias: the
  // input path (response.h) must reproduce LinearErrorModel's column.
  const Layout l = layout(6300.0);
  const RecordSite s = site();
  const Eigen::MatrixXd x = uncertainty_response(l, s);
  for (int k = 0; k < 2; ++k) {
    InputSignal in;
    in.columns = 1;
    in.at = [k](double, Columns3& a, Columns3& th) {
      a.setZero();
      th.setZero();
      a(k, 0) = 1.0;
    };
    const Eigen::MatrixXd r = input_response(l, s, in);
    const Eigen::VectorXd col = x.col(ux::kBiasChangeConst + k);
    EXPECT_LT((r.col(0) - col).cwiseAbs().maxCoeff(), 1e-9 * col.cwiseAbs().maxCoeff()) << k;
  }
}

TEST(GapResponse, APlatformTiltIsSeenAsGravityAcrossTheAccelerometers) {
  // f^a = (I − [θ×]) f^{a'} with f^{a'} = (0, 0, −g) at t = 0: a tilt θ_y gives
  // f_x = g θ_y and a tilt θ_x gives f_y = −g θ_x.
  const Layout l = layout(60.0);
  const RecordSite s = site();
  InputSignal in;
  in.columns = 2;
  in.at = [](double, Columns3& a, Columns3& th) {
    a.setZero();
    th.setZero();
    th(1, 0) = 1.0;
    th(0, 1) = 1.0;
  };
  const Eigen::MatrixXd r = input_response(l, s, in);
  const double g = s.model.gravity_mps2;
  ASSERT_EQ(l.rows[0].quantity, Quantity::kF);
  EXPECT_NEAR(r(0, 0), g, 1e-3 * g);   // f_x at t = 10 s, θ_y
  EXPECT_NEAR(r(1, 1), -g, 1e-3 * g);  // f_y, θ_x
}

/// Per-run group sums of `runs` draws y = H c + e, c from the model's priors
/// and e with the variances `noise_var`.
std::vector<GroupSums> sums_of_draws(const GaussianModel& m, const RunAnalyser& a, const Eigen::VectorXd& noise_var,
                                     std::uint64_t seed, int runs = 400) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> n01;
  std::vector<GroupSums> out;
  for (int r = 0; r < runs; ++r) {
    Eigen::VectorXd c(m.prior_var.size()), e(noise_var.size());
    for (Eigen::Index j = 0; j < c.size(); ++j) c[j] = std::sqrt(m.prior_var[j]) * n01(rng);
    for (Eigen::Index i = 0; i < e.size(); ++i) e[i] = std::sqrt(noise_var[i]) * n01(rng);
    out.push_back(a.analyse(m.H * c + e));
  }
  return out;
}

/// Per group, the mean over runs of the mean z² against want(g), within 4.5
/// standard errors of the per-run means (independent across runs; a false
/// failure ~7e-6 per group). Returns the groups checked.
template <class Want>
int expect_group_means(const std::vector<GroupSums>& runs, const Want& want) {
  int checked = 0;
  for (int g = 0; g < kGroupCount; ++g) {
    if (!(runs.front().count[g] > 0)) continue;
    double sum = 0, sq = 0;
    for (const GroupSums& r : runs) {
      const double v = r.z2[g] / r.count[g];
      sum += v, sq += v * v;
    }
    const auto n = static_cast<double>(runs.size());
    const double mean = sum / n, sd = std::sqrt((sq - n * mean * mean) / (n - 1));
    EXPECT_LT(std::abs(mean - want(g)), 4.5 * sd / std::sqrt(n)) << group_name(g) << " mean " << mean << " want " << want(g);
    ++checked;
  }
  return checked;
}

TEST(GapAnalysis, NormalizedSquaresAverageOneOnDataDrawnFromTheModel) {
  // E z² = 1 per group for data y = H c + e drawn with the model's own second moments.
  const Layout l = layout(3600.0);
  const RecordSite s = site();
  const GaussianModel m = combine(make_base_model(l, s, UncertaintyModel{}.variance()), {});
  const RunAnalyser a(l, m);
  EXPECT_GT(expect_group_means(sums_of_draws(m, a, m.noise_var, 7), [](int) { return 1.0; }), 0);
}

TEST(GapAnalysis, ActualSquaresAverageWhatDrawsWithTheActualNoiseGive) {
  // The fit weights rows with the model-error floor; data drawn with only
  // the actual noise (position resolution, counting) must average the
  // expected squares E_i/e_i of run_analysis.h, group by group.
  const Layout l = layout(3600.0);
  RecordSite s = site();
  s.position_resolution_m = 3 * kFtToM;
  const GaussianModel m = combine(make_base_model(l, s, UncertaintyModel{}.variance()), {});
  const RunAnalyser a(l, m);
  const std::vector<GroupSums> runs = sums_of_draws(m, a, m.actual_noise_var, 11);
  const GroupSums& one = runs.front();  // E/e depends on the layout only
  expect_group_means(runs, [&](int g) { return one.expected[g] / one.count[g]; });
  // Groups where the floor, not the data, sets the normalizer: the check is
  // not the trivial E = e there (the test-run r groups at least).
  int floored = 0;
  for (int g = 0; g < kGroupCount; ++g) floored += one.count[g] > 0 && one.expected[g] < 0.5 * one.count[g];
  EXPECT_GE(floored, 3);
}

TEST(GapLayout, ARunThatStoppedEarlyBeginsTheLongerLayout) {
  const Layout longer = layout(3600.0), shorter = layout(1800.0);
  EXPECT_EQ(rows_begun(shorter, longer), shorter.rows.size());  // its last r row (t = 1800 s) is in both
  // A run that stopped at 1830 s keeps the r row at 1830 s that the longer
  // layout (r rows each 60 s) has not: all but that row begin it.
  Layout stopped = layout(1830.0);
  for (int k = 0; k < 3; ++k) stopped.rows.push_back({1830.0, Quantity::kR, k, stopped.rows.back().group});
  EXPECT_EQ(rows_begun(stopped, longer), stopped.rows.size() - 3);
  Layout other_test = shorter;
  other_test.test_rows -= 3;
  EXPECT_EQ(rows_begun(other_test, longer), 0U);
  EXPECT_EQ(rows_begun(longer, shorter), 0U);
}

TEST(GapAnalysis, ARunThatStoppedEarlyGetsTheSumsOfItsOwnLayout) {
  // The diagnosis analyses a shortened run under the longer layout it
  // begins (one analyser for both); its sums must be those of its own
  // layout's model, built from scratch.
  const Layout longer = layout(3600.0), shorter = layout(1800.0);
  // Continuous f: pulse counting's integration steps follow a layout's
  // length (pulse_counting.h), and would differ by their round-off alone.
  RecordSite s = site();
  s.dv_pulse_mps = 0.0;
  const UncertaintyVector x_var = UncertaintyModel{}.variance();
  const GaussianModel m_longer = combine(make_base_model(longer, s, x_var), {});
  const GaussianModel m_shorter = combine(make_base_model(shorter, s, x_var), {});
  const auto n = static_cast<Eigen::Index>(shorter.rows.size());
  const GaussianModel m_first = first_rows(m_longer, n);
  EXPECT_LT((m_first.H - m_shorter.H).cwiseAbs().maxCoeff(), 1e-9 * m_shorter.H.cwiseAbs().maxCoeff());
  const RunAnalyser shared(longer, m_longer), own(shorter, m_shorter);
  std::mt19937_64 rng(5);
  std::normal_distribution<double> n01;
  for (int draw = 0; draw < 3; ++draw) {
    Eigen::VectorXd c(m_shorter.prior_var.size()), e(n);
    for (Eigen::Index j = 0; j < c.size(); ++j) c[j] = std::sqrt(m_shorter.prior_var[j]) * n01(rng);
    for (Eigen::Index i = 0; i < n; ++i) e[i] = std::sqrt(m_shorter.noise_var[i]) * n01(rng);
    const Eigen::VectorXd y = m_shorter.H * c + e;
    const GroupSums a = shared.analyse(y), b = own.analyse(y);
    for (int g = 0; g < kGroupCount; ++g) {
      EXPECT_EQ(a.count[g], b.count[g]) << group_name(g);
      EXPECT_NEAR(a.z2[g], b.z2[g], 1e-7 * (1.0 + b.z2[g])) << group_name(g);
      EXPECT_NEAR(a.expected[g], b.expected[g], 1e-7 * (1.0 + b.expected[g])) << group_name(g);
    }
  }
}

TEST(GapModel, ACandidateWideningThePriorsKeepsTheFloorTheNullWasCalibratedOn) {
  // The floor's relative part follows the base model's priors (what
  // --bound sets and the null is simulated with), not a candidate's: the
  // null's κ and λ are shares of that floor.
  const Layout l = layout(3600.0);
  const RecordSite s = site();
  const UncertaintyVector table = UncertaintyModel{}.variance();
  const BaseModel base = make_base_model(l, s, table);
  Extension wider;
  wider.x_var_scale.setConstant(100.0);
  const GaussianModel m = combine(base, {&wider});
  EXPECT_EQ(m.prior_var.head(ux::kDim), 100.0 * table);
  const GaussianModel plain = combine(base, {});
  EXPECT_EQ(m.noise_var, plain.noise_var);
  // A base of wider priors has a wider floor on the r rows, none on f.
  const BaseModel widened = make_base_model(l, s, 100.0 * table);
  int wider_rows = 0;
  for (std::size_t i = 0; i < l.rows.size(); ++i) {
    const auto k = static_cast<Eigen::Index>(i);
    if (l.rows[i].quantity == Quantity::kR) {
      EXPECT_GT(widened.noise_var[k], base.noise_var[k]) << l.rows[i].t_s;
      ++wider_rows;
    } else {
      EXPECT_EQ(widened.noise_var[k], base.noise_var[k]) << l.rows[i].t_s;
    }
  }
  EXPECT_GT(wider_rows, 0);
}

TEST(GapMetric, IsTheRmsOfTheGroupsLogRatiosAgainstTheCalibratedExpectation) {
  // One run: what it shares with itself is its own scatter (coherent ℓ = 0).
  Pooled one;
  one.runs = 1;
  for (int g = 0; g < 4; ++g) one.power.z2[g] = 10.0, one.power.count[g] = 10.0, one.power.expected[g] = 10.0;
  for (int g = 0; g < 4; ++g) one.coherent[static_cast<std::size_t>(coherent_group_of(g))] += one.power.z2[g];
  NullCalibration none;
  EXPECT_DOUBLE_EQ(gap_value(one, none), 0.0);
  const int present = 4 + 4;  // four scatter groups and the four coherent groups they fall in
  one.power.z2[0] = 10.0 * std::exp(2.0);  // one group off by e² in power
  one.coherent[0] = one.power.z2[0];
  EXPECT_NEAR(gap_value(one, none), std::sqrt(4.0 / present), 1e-12);
  one.power.z2[1] = 10.0 * std::exp(-2.0);  // too little scatter counts as much as too much
  one.coherent[1] = one.power.z2[1];
  EXPECT_NEAR(gap_value(one, none), std::sqrt(8.0 / present), 1e-12);
  // The floor's share: a group whose actual expectation is 2 of 10 and
  // whose floor adds 8 expects 2 + κ 8.
  Pooled f;
  f.runs = 1;
  f.power.z2[0] = 6.0, f.power.count[0] = 10.0, f.power.expected[0] = 2.0, f.power.floor[0] = 8.0;
  NullCalibration half;
  half.floor_share[0] = 0.5;
  EXPECT_NEAR(log_ratios(f, half).scatter[0], 0.0, 1e-12);
  // The floor is an allowance: anything from the actual expectation (2,
  // the linear level without second-order terms) to 2 + κ 8 agrees; beyond
  // either end the ratio is to that end.
  for (double inside : {2.0, 3.0, 6.0}) {
    f.power.z2[0] = inside;
    EXPECT_DOUBLE_EQ(log_ratios(f, half).scatter[0], 0.0) << inside;
  }
  f.power.z2[0] = 0.5;
  EXPECT_NEAR(log_ratios(f, half).scatter[0], std::log(0.5 / 2.0), 1e-12);
  f.power.z2[0] = 12.0;
  EXPECT_NEAR(log_ratios(f, half).scatter[0], std::log(12.0 / 6.0), 1e-12);
}

TEST(GapMetric, CoherentGroupsSeeOnlyWhatRunsShareBeyondIndependence) {
  // Two runs with the same values in a group share all of it: C = 2 D, ℓ = ln 2;
  // opposite values share nothing positive: one-sided, ℓ = 0.
  KeySpace keys;
  Layout l;
  for (int k = 0; k < 3; ++k) l.rows.push_back({60.0, Quantity::kR, k, group_of(Stage::kTest, Quantity::kR, k, 0)});
  l.test_rows = 3;
  keys.add_layout(l);
  Eigen::MatrixXd same = Eigen::MatrixXd::Zero(keys.size(), 2), opposite = same;
  same(0, 0) = same(0, 1) = 1.5;
  opposite(0, 0) = 1.5, opposite(0, 1) = -1.5;
  GroupSums run;
  const int g = group_of(Stage::kTest, Quantity::kR, 0, 0), c = coherent_group_of(g);
  run.z2[g] = 2.25, run.count[g] = 1.0, run.expected[g] = 2.25;
  const std::vector<int> both = {0, 1};
  const NullCalibration none;
  EXPECT_NEAR(log_ratios(pool(make_run_set({run, run}, same, keys), both), none).coherent[static_cast<std::size_t>(c)],
              std::log(2.0), 1e-12);
  EXPECT_NEAR(log_ratios(pool(make_run_set({run, run}, opposite, keys), both), none).coherent[static_cast<std::size_t>(c)],
              0.0, 1e-12);
  // A multiset counts a repeated run twice: three copies share 3 D.
  EXPECT_NEAR(log_ratios(pool(make_run_set({run, run}, same, keys), std::vector<int>{0, 0, 1}), none)
                  .coherent[static_cast<std::size_t>(c)],
              std::log(3.0), 1e-12);
  // Runs alike to the last digit but a hundred times below the model's
  // scatter (a perfect sensor) share nothing the model would notice: the
  // reference is the model's scatter then, and with 200 such runs the
  // shared part reaches it only at 200 × 1e-4 / 2.25 < 1.
  GroupSums tiny = run;
  tiny.z2[g] = 1e-4;
  Eigen::MatrixXd alike = Eigen::MatrixXd::Zero(keys.size(), 200);
  alike.row(0).setConstant(1e-2);
  std::vector<int> all(200);
  for (int k = 0; k < 200; ++k) all[static_cast<std::size_t>(k)] = k;
  const auto significance = CoherentReference::kAtLeastModelScatter;
  EXPECT_NEAR(log_ratios(pool(make_run_set(std::vector<GroupSums>(200, tiny), alike, keys), all), none, significance)
                  .coherent[static_cast<std::size_t>(c)],
              0.0, 1e-12);
  // Comparing candidates, the runs' own scatter stays the reference: a
  // candidate that only widens the model cannot explain what runs share.
  EXPECT_NEAR(log_ratios(pool(make_run_set(std::vector<GroupSums>(200, tiny), alike, keys), all), none)
                  .coherent[static_cast<std::size_t>(c)],
              std::log(200.0), 1e-9);
  // … and when what they share outgrows the model's scatter, it counts:
  // 200 runs × 0.04 = 8 against the model's 2.25.
  tiny.z2[g] = 0.04;
  alike.row(0).setConstant(0.2);
  EXPECT_NEAR(log_ratios(pool(make_run_set(std::vector<GroupSums>(200, tiny), alike, keys), all), none, significance)
                  .coherent[static_cast<std::size_t>(c)],
              std::log(200 * 0.04 / 2.25), 1e-9);
  // Null runs that share a systematic part calibrate it away: λ from their
  // pairs over the floor one run contributes.
  GroupSums floored = run;
  floored.floor[g] = 2.25;
  const RunSet null = make_run_set({floored, floored}, same, keys);
  const NullCalibration cal = NullCalibration::from_null(null);
  EXPECT_NEAR(cal.systematic[static_cast<std::size_t>(c)], 1.0, 1e-12);  // pairs 2.25 over floor 2.25
  EXPECT_NEAR(cal.floor_share[g], 0.0, 1e-12);  // z² = the actual expectation: the floor adds nothing
  // κ: the share of the floor the null's z² shows, (z² − expected) / floor.
  GroupSums half_floored = floored;
  half_floored.z2[g] = 2.25 + 0.5 * 2.25;
  EXPECT_NEAR(NullCalibration::from_null(make_run_set({half_floored, half_floored}, same, keys)).floor_share[g], 0.5,
              1e-12);
  EXPECT_NEAR(log_ratios(pool(null, both), cal).coherent[static_cast<std::size_t>(c)], 0.0, 1e-12);
}

TEST(GapPulseCounting, TheSawtoothIntegralIsExact) {
  // ∫ e dt over a step on which V is linear, against a fine midpoint sum.
  const double w = 0.3;
  for (const auto& [v0, v1, phase] : {std::tuple{0.0, 0.05, 0.2}, std::tuple{-0.4, 2.7, -0.45},
                                      std::tuple{5.0, 4.1, 0.0}, std::tuple{1.0, 1.0, 0.3}}) {
    const double h = 5.0;
    constexpr int kSteps = 200000;
    double sum = 0.0;
    for (int i = 0; i < kSteps; ++i) {
      const double u = (i + 0.5) / kSteps;
      sum += counting_velocity_error(v0 + u * (v1 - v0), phase, w) * h / kSteps;
    }
    // The midpoint sum errs by at most a pulse over one sub-step at each of
    // the |Δv|/w + 1 jumps of the sawtooth.
    const double jumps = std::abs(v1 - v0) / w + 1.0;
    EXPECT_NEAR(counting_velocity_error_integral(v0, v1, h, phase, w), sum, jumps * w * h / kSteps) << v0 << " " << v1;
  }
  EXPECT_DOUBLE_EQ(counting_velocity_error(0.0, 0.37, w), 0.0);  // no pulse, no error
}

TEST(GapPulseCounting, PositionScatterMatchesTheTruthSimulatorsCounters) {
  // Truth runs with pulses of w less the same runs with a continuous output
  // isolate what the counters do to r: on x an offset that switches on
  // minutes into the run, on y and z at once. Their variance per axis and
  // window against the model's (columns² + rest), as a log ratio; bound 4.5
  // standard errors of the log of two variance estimates from N truth runs
  // and the model's 256 draws, sqrt(2/N + 2/256).
  Layout l;
  for (double t = 30.0; t <= 2700.0; t += 30.0)
    for (int k = 0; k < 3; ++k) l.rows.push_back({t, Quantity::kR, k, group_of(Stage::kTest, Quantity::kR, k, 0)});
  l.test_rows = static_cast<int>(l.rows.size());
  RecordSite s = site();
  const double w = 0.5;
  s.dv_pulse_mps = w;
  const UncertaintyModel prior;
  const PulseCounting pc =
      pulse_counting(l, s, w, prior.variance(), Eigen::VectorXd::Ones(static_cast<Eigen::Index>(l.rows.size())));
  const Eigen::VectorXd model = pc.columns.rowwise().squaredNorm() + pc.noise_var;
  TruthOptions o;
  o.model = s.model;
  o.system = s.system;
  std::vector<double> times;
  for (double t = 30.0; t <= 2700.0; t += 30.0) times.push_back(t);
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  constexpr int kRuns = 300;
  Eigen::VectorXd truth = Eigen::VectorXd::Zero(model.size());
  for (int r = 0; r < kRuns; ++r) {
    UncertaintyVector x;  // uniform with the priors' variance
    for (int j = 0; j < ux::kDim; ++j) x[j] = std::sqrt(3.0 * prior.variance()[j]) * (2.0 * u01(rng) - 1.0);
    TruthOptions pulsed = o, continuous = o;
    pulsed.dv_pulse_mps = w;
    for (int k = 0; k < 3; ++k) pulsed.pulse_phase[k] = u01(rng) - 0.5;
    continuous.dv_pulse_mps = 0.0;
    const TruthRun a = simulate_truth(pulsed, x, times), b = simulate_truth(continuous, x, times);
    for (std::size_t i = 0; i < l.rows.size(); ++i) {
      const auto k = static_cast<std::size_t>(i / 3);
      const double d = a.position_error_ap_m[k][l.rows[i].axis] - b.position_error_ap_m[k][l.rows[i].axis];
      truth[static_cast<Eigen::Index>(i)] += d * d / kRuns;
    }
  }
  const double bound = 4.5 * std::sqrt(2.0 / kRuns + 2.0 / 256.0);
  for (int axis = 0; axis < 3; ++axis) {
    for (const auto& [from, to] : {std::pair{30.0, 600.0}, std::pair{600.0, 1200.0}, std::pair{1200.0, 2700.0}}) {
      double m = 0, t = 0;
      for (std::size_t i = 0; i < l.rows.size(); ++i)
        if (l.rows[i].axis == axis && l.rows[i].t_s >= from && l.rows[i].t_s <= to)
          m += model[static_cast<Eigen::Index>(i)], t += truth[static_cast<Eigen::Index>(i)];
      std::printf("counting axis %d %4.0f-%4.0f s: model/truth %.3f\n", axis, from, to, m / t);
      EXPECT_LT(std::abs(std::log(m / t)), bound) << "axis " << axis << " " << from << "-" << to << " s: model " << m
                                                  << " truth " << t;
    }
  }
}

TEST(GapCandidates, EveryGridPointBuildsAConsistentExtension) {
  const Layout l = layout(2400.0);
  const RecordSite s = site();
  const BaseModel base = make_base_model(l, s, UncertaintyModel{}.variance());
  for (const Candidate& c : candidate_registry()) {
    const LayoutContext ctx{&l, &s, &base, {}};
    const std::vector<int> amplitudes = c.amplitude_indices();
    ASSERT_TRUE(c.grid_size() > 1 || !amplitudes.empty()) << c.name << ": nothing to fit";
    for (int j : amplitudes) {
      // The least-squares fit of an amplitude needs a mean linear in it.
      std::vector<double> theta = c.grid_point(0);
      theta[static_cast<std::size_t>(j)] = 1.0;
      const Eigen::VectorXd one = c.build(ctx, theta).mean;
      theta[static_cast<std::size_t>(j)] = -2.5;
      const Eigen::VectorXd scaled = c.build(ctx, theta).mean;
      ASSERT_EQ(one.size(), static_cast<Eigen::Index>(l.rows.size())) << c.name;
      EXPECT_GT(one.norm(), 0.0) << c.name;
      EXPECT_LE((scaled + 2.5 * one).norm(), 1e-12 * one.norm()) << c.name;
      EXPECT_TRUE(c.build(ctx, c.grid_point(0)).mean_only()) << c.name;
    }
    for (int k : {0, c.grid_size() - 1}) {
      const Extension e = c.build(ctx, c.grid_point(k));
      EXPECT_EQ(e.columns.cols(), e.column_var.size()) << c.name;
      if (e.columns.cols() > 0) {
        EXPECT_EQ(e.columns.rows(), static_cast<Eigen::Index>(l.rows.size())) << c.name;
      }
      if (e.mean.size() > 0) {
        EXPECT_EQ(e.mean.size(), static_cast<Eigen::Index>(l.rows.size())) << c.name;
      }
      if (e.noise_var_add.size() > 0) {
        EXPECT_EQ(e.noise_var_add.size(), static_cast<Eigen::Index>(l.rows.size())) << c.name;
        EXPECT_GE(e.noise_var_add.minCoeff(), 0.0) << c.name;
      }
      EXPECT_GE(e.x_var_add.minCoeff(), 0.0) << c.name;
      const GaussianModel m = combine(base, {&e});
      EXPECT_NO_FATAL_FAILURE(RunAnalyser(l, m)) << c.name;
    }
  }
}

TEST(GapLayout, RecordsOfOtherSoftwareAreTakenAsTheyCome) {
  // f every 5 s (windows of 10 s overlap: every other is kept), an f gap,
  // r every 20 s, a run that stops early, arbitrary run numbers.
  RecordFile file;
  file.header = RecordHeader::make(45.0, System::kTheodolite, 900.0, Scheme::kNone);
  for (std::int64_t id : {17, -3}) {
    RecordRun run;
    run.id = id;
    const double end = id == 17 ? 6300.0 : 2000.0;
    for (double t = 5.0; t <= end; t += 5.0) {
      RecordRow row;
      row.run = id;
      row.t_s = t;
      row.phase = t <= 900.0 ? Phase::kTest : Phase::kNav;
      if (!(t > 300.0 && t < 400.0)) row.f_mps2 = {1e-4, 2e-4, 3e-4};
      row.r_ap_m = std::fmod(t, 20.0) == 0.0 ? OptionalVector3(Eigen::Vector3d(1.0, 2.0, 3.0)) : OptionalVector3();
      if (row.r_ap_m || row.has_f()) run.rows.push_back(row);
    }
    file.runs.push_back(run);
  }
  EXPECT_DOUBLE_EQ(median_f_spacing(file), 5.0);
  {
    // Navigation f of another writer's sampling (every 10 s, outnumbering
    // the test's 5 s rows) does not set the test run's filter interval.
    RecordFile sparse = file;
    for (RecordRun& run : sparse.runs)
      for (RecordRow& row : run.rows)
        if (row.phase == Phase::kNav && std::fmod(row.t_s, 10.0) != 0.0) row.f_mps2 = {};
    EXPECT_DOUBLE_EQ(median_f_spacing(sparse), 5.0);
  }
  RecordSite s = site();
  const std::vector<RunData> runs = extract_runs(file, s);
  ASSERT_EQ(runs.size(), 2u);
  EXPECT_EQ(runs[0].id, 17);
  for (const RunData& r : runs) {
    double last_f = -1e9, last_r = -1e9;
    for (const ObservationRow& row : r.layout.rows) {
      if (row.axis != 0) continue;
      if (row.quantity == Quantity::kF) {
        EXPECT_GE(row.t_s - last_f, 10.0 - 1e-9);
        EXPECT_FALSE(row.t_s > 300.0 && row.t_s < 400.0);
        last_f = row.t_s;
      } else {
        EXPECT_TRUE(row.t_s - last_r >= 30.0 - 1e-9 || row.t_s == r.end_s) << row.t_s;  // the last always counts
        last_r = row.t_s;
      }
    }
    EXPECT_EQ(r.values.size(), r.layout.rows.size());
  }
  EXPECT_DOUBLE_EQ(runs[1].end_s, 2000.0);
}

}  // namespace
}  // namespace insmc::gap
